// Replacing a file so that a failed or interrupted write never leaves a truncated one.
#ifndef RadiosityCore_AtomicFile_h
#define RadiosityCore_AtomicFile_h

#include <functional>
#include <string>

namespace radiosity
{

/// Calls write(temporary, created) to write a temporary file beside `path`, then renames
/// it over `path`. `write` sets `created` once its file exists (only a file made here is
/// removed when `write` throws; the exception passes on). Returns an empty string or
/// why the rename failed.
std::string WriteAtomically(const std::string& path, const std::function<void(const char*, bool&)>& write);

} // namespace radiosity

#endif
