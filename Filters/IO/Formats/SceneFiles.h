// Reading scene files into the core's RawScene: VTK's readers for OBJ+MTL, glTF/GLB, PLY
// and VRML; assimp's command-line tool for the formats VTK lacks (IFC, FBX,
// DAE, 3DS, ...). Formats() in SceneFiles.cxx is the one list of them.
// Each returns an empty string or what is wrong, naming the file (not wrapped).
#ifndef SceneFiles_h
#define SceneFiles_h

#include "Import/SceneImport.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkMatrix4x4;
class vtkPolyData;

namespace SceneFiles
{

/// Dispatches on the file's extension; `warnings` collects what was read but not used.
std::string Read(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);

std::string ReadObj(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);
/// ReadObj with the material libraries' textures looked for in `textureFolder` (the model's
/// own folder for a file assimp converted into a temporary one).
std::string ReadObjTexturedFrom(const std::string& path, const std::string& textureFolder, radiosity::RawScene& raw,
  std::vector<std::string>& warnings);
std::string ReadGltf(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);
std::string ReadPly(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);
/// Empty when every count, list and face index of the PLY file fits what the file holds;
/// otherwise the error (vtkPLYReader would crash on such a file). `realColors` (optional):
/// set when a color property (red, green, blue) is a float or double, which vtkPLYReader
/// takes as an 8-bit value (1.0 as 1 of 255).
std::string CheckPly(const std::string& path, bool* realColors = nullptr);

/// What VTK's VRML importer would crash on in this (comment-free) VRML97 text, naming its
/// line ("line 4: USE Wall with no DEF Wall before it"); empty if nothing.
std::string CheckVrmlText(const std::string& text);
std::string ReadVrml(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);
std::string ReadWithAssimp(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings);

/// The whole file as bytes; false where it cannot be opened.
bool ReadText(const std::string& path, std::string& text);
/// True for a file that holds data (not a folder, FIFO or device: reading those blocks or
/// never ends).
bool RegularFile(const std::string& path);

using ReadFunction = std::string (*)(const std::string&, radiosity::RawScene&, std::vector<std::string>&);

/// One row of the table of scene formats: the one place a format is registered. The
/// reader dispatches on it, CanReadFile and the "unknown extension" error are made from
/// it, and Python.TestNames checks the ParaView reader hint against it.
struct Format
{
  const char* Name;
  std::vector<std::string> Extensions; ///< lower case, without the dot
  ReadFunction Read;
  bool NeedsAssimp; ///< read through assimp's command-line tool
};
const std::vector<Format>& Formats();
/// The row for a file's extension (any case); null where no format has it.
const Format* FormatOf(const std::string& path);
/// Every extension of every format, space-separated, in table order.
std::string AllExtensions();

/// Appends `data`'s polygons (points through `transform` if given) with one material and
/// object; returns the number of cells that were not polygons (lines, points) and so left out.
int AppendPolygons(vtkPolyData* data, const vtkMatrix4x4* transform, int material, int object,
  radiosity::RawScene& raw);

/// A fresh folder under the system's temporary directory, removed with its files when
/// this goes away.
class TemporaryFolder
{
public:
  TemporaryFolder();
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  std::string Path;
};

/// A binary glTF file's bytes: header, the JSON chunk (space padded) and, when not
/// empty, the binary chunk (zero padded). False when it would pass glTF's 4 GiB limit.
bool GlbBytes(const std::string& json, const std::string& binary, std::string& bytes);

/// An sRGB-encoded value in [0, 1] as linear light.
double SrgbToLinear(double encoded);

/// The mean linear RGB of an image: integer (8 or 16 bit) sRGB codes made linear, float
/// values as they are, grey counted for all channels; white if there is none.
radiosity::Vec3 MeanColor(vtkImageData* image);

}

#endif
