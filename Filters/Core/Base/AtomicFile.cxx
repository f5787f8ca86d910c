#include "Base/AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace radiosity
{

std::string WriteAtomically(const std::string& path, const std::function<void(const char*, bool&)>& write)
{
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code unknown; // a folder that cannot be examined: the open says why
  if (!folder.empty() && !std::filesystem::exists(folder, unknown) && !unknown)
  {
    return "the folder '" + folder.string() + "' does not exist"; // not "cannot open <path>.part"
  }
  const std::string temporary = path + ".part";
  bool created = false;
  try
  {
    write(temporary.c_str(), created);
  } // the file is closed (and flushed) before it replaces the old one
  catch (...)
  {
    if (created)
    {
      std::remove(temporary.c_str());
    }
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    return "could not replace " + path + ": " + reason;
  }
  return std::string();
}

} // namespace radiosity
