// Formats VTK does not read (IFC, FBX, DAE, 3DS, ...): Debian's `assimp` tool converts
// them to OBJ + MTL in a temporary folder (scene-graph transforms applied), which is then
// read as any OBJ.
#include "SceneFiles.h"
#include "Base/Text.h"

#include <vtksys/Process.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>


namespace SceneFiles
{
namespace
{

/// Runs `assimp export in out`; empty string or what went wrong.
std::string RunAssimp(const std::string& program, const std::string& in, const std::string& out)
{
  const char* command[] = { program.c_str(), "export", in.c_str(), out.c_str(), nullptr };
  vtksysProcess* process = vtksysProcess_New();
  vtksysProcess_SetCommand(process, command);
  vtksysProcess_SetOption(process, vtksysProcess_Option_HideWindow, 1);
  double timeout = 600; // seconds; a huge model converts in well under that
  vtksysProcess_SetTimeout(process, timeout);
  vtksysProcess_Execute(process);
  std::string output;
  char* data = nullptr;
  int length = 0;
  while (vtksysProcess_WaitForData(process, &data, &length, nullptr))
  {
    output.append(data, length);
  }
  vtksysProcess_WaitForExit(process, nullptr);
  const int state = vtksysProcess_GetState(process);
  const int code = state == vtksysProcess_State_Exited ? vtksysProcess_GetExitValue(process) : -1;
  vtksysProcess_Delete(process);
  if (state == vtksysProcess_State_Expired)
  {
    return "assimp took more than " + std::to_string(static_cast<int>(timeout)) + " s and was stopped";
  }
  if (code == 0 && vtksys::SystemTools::FileExists(out, true))
  {
    return std::string();
  }
  // assimp's own reason is its last non-empty line.
  std::vector<std::string> lines;
  vtksys::SystemTools::Split(output, lines, '\n');
  std::string reason;
  for (const std::string& line : lines)
  {
    if (!radiosity::Trimmed(line).empty())
    {
      reason = radiosity::Trimmed(line);
    }
  }
  return reason.empty() ? "assimp failed" : "assimp: " + reason;
}

/// The double after the name's three string fields in a binary FBX property record
/// (S type, S label, S flags, D value); 0 where the bytes are not laid out so.
double BinaryFbxValue(const std::string& data, size_t at)
{
  for (int field = 0; field < 3; ++field)
  {
    std::uint32_t length = 0;
    if (at + 5 > data.size() || data[at] != 'S')
    {
      return 0.0;
    }
    std::memcpy(&length, data.data() + at + 1, 4);
    at += 5 + static_cast<size_t>(length);
  }
  double value = 0;
  if (at + 9 > data.size() || data[at] != 'D')
  {
    return 0.0;
  }
  std::memcpy(&value, data.data() + at + 1, 8); // FBX is little-endian, as this machine
  return value;
}

/// Metres per unit of an FBX file from its UnitScaleFactor (centimetres per unit), which
/// assimp's export leaves unapplied (Collada's unit it applies); 0 where the file says none.
double FbxMetresPerUnit(const std::string& path)
{
  std::string data;
  if (!ReadText(path, data))
  {
    return 0.0;
  }
  double centimetres = 0;
  const std::string binary = std::string("S\x0f\0\0\0", 5) + "UnitScaleFactor";
  const size_t at = data.find(binary);
  if (at != std::string::npos)
  {
    centimetres = BinaryFbxValue(data, at + binary.size());
  }
  else if ((data.find("\"UnitScaleFactor\"")) != std::string::npos)
  {
    // P: "UnitScaleFactor", "double", "Number", "",2.54
    size_t comma = data.find("\"UnitScaleFactor\"");
    for (int field = 0; field < 4 && comma != std::string::npos; ++field)
    {
      comma = data.find(',', comma + 1);
    }
    centimetres = comma == std::string::npos ? 0.0 : std::strtod(data.c_str() + comma + 1, nullptr);
  }
  return std::isfinite(centimetres) && centimetres > 0 && centimetres < 1e9 ? centimetres / 100.0 : 0.0;
}

} // namespace

/// An IFC (STEP) file starts with ISO-10303-21; and ends with END-ISO-10303-21; assimp
/// reads a cut one without a word, as the part of the building before the cut.
std::string CheckStepEnd(const std::string& path)
{
  const std::string extension = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (extension != ".ifc")
  {
    return std::string();
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  std::string start(13, ' ');
  in.seekg(0);
  in.read(&start[0], 13);
  if (start != "ISO-10303-21;")
  {
    return std::string(); // not STEP at all: assimp says what it makes of it
  }
  const std::streamoff tail = std::min<std::streamoff>(size, 256);
  std::string end(static_cast<size_t>(std::max<std::streamoff>(tail, 0)), ' ');
  in.seekg(size - tail);
  in.read(&end[0], tail);
  const size_t last = end.find_last_not_of(" \t\r\n");
  const std::string mark = "END-ISO-10303-21;";
  const bool whole = last != std::string::npos && last + 1 >= mark.size() &&
    end.compare(last + 1 - mark.size(), mark.size(), mark) == 0;
  return whole ? std::string() : "'" + path + "' does not end with END-ISO-10303-21; (the file is cut short)";
}

std::string ReadWithAssimp(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  const std::string cut = CheckStepEnd(path);
  if (!cut.empty())
  {
    return cut;
  }
  const std::string program = vtksys::SystemTools::FindProgram("assimp");
  if (program.empty())
  {
    return "'" + path + "' needs assimp to be read, and the 'assimp' program is not installed "
                        "(Debian: apt-get install assimp-utils; or convert the file to glTF or OBJ)";
  }
  const TemporaryFolder folder;
  const std::string converted = folder.Path + "/scene.obj";
  const std::string error = RunAssimp(program, path, converted);
  if (!error.empty())
  {
    return "'" + path + "' could not be converted (" + error + ")";
  }
  // Textures stay beside the model; the OBJ is in a temporary folder.
  const std::string model = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path));
  const std::string read = ReadObjTexturedFrom(converted, model, raw, warnings);
  if (!read.empty())
  {
    return "'" + path + "' converted by assimp: " + read;
  }
  const bool fbx = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path)) == ".fbx";
  const double metres = fbx ? FbxMetresPerUnit(path) : 0.0;
  for (radiosity::Vec3& p : raw.Points)
  {
    p = metres > 0 ? p * metres : p;
  }
  return std::string();
}

}
