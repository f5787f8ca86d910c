#include "SceneFiles.h"
#include "SceneFilesErrors.h"
#include "Base/Text.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <random>

namespace SceneFiles
{
namespace
{
/// Adds one polygon of point ids (offset into raw.Points) with its material and object;
/// `mirrored` reverses the corners (a transform with a negative determinant turns faces).
void AddPolygon(const vtkIdType* ids, vtkIdType count, int base, int material, int object, bool mirrored,
  radiosity::RawScene& raw)
{
  for (vtkIdType k = 0; k < count; ++k)
  {
    raw.Connectivity.push_back(base + static_cast<int>(ids[mirrored ? count - 1 - k : k]));
  }
  raw.Offsets.push_back(static_cast<int>(raw.Connectivity.size()));
  raw.Material.push_back(material);
  raw.Object.push_back(object);
}

/// A strip a b c d ... as triangles (a b c), (c b d), ... keeping one orientation.
void AddStrip(const vtkIdType* ids, vtkIdType count, int base, int material, int object, bool mirrored,
  radiosity::RawScene& raw)
{
  for (vtkIdType k = 0; k + 2 < count; ++k)
  {
    const vtkIdType even[3] = { ids[k], ids[k + 1], ids[k + 2] };
    const vtkIdType odd[3] = { ids[k + 1], ids[k], ids[k + 2] };
    AddPolygon(k % 2 ? odd : even, 3, base, material, object, mirrored, raw);
  }
}


} // namespace

bool RegularFile(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

/// Edits (insert, delete, replace a character) from `a` to `b`.
size_t EditDistance(const std::string& a, const std::string& b)
{
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (size_t i = 1; i <= a.size(); ++i)
  {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
    {
      const size_t above = row[j];
      row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1) });
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// " (did you mean 'x'?)" for the file of the missing path's folder whose name is a
/// typo or two away from it, or nothing.
std::string NearestFile(const std::string& path)
{
  const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
  const std::string name = vtksys::SystemTools::GetFilenameName(path);
  vtksys::Directory listing;
  if (name.empty() || !listing.Load(folder.empty() ? "." : folder))
  {
    return std::string();
  }
  std::string best;
  size_t nearest = std::max<size_t>(1, std::min<size_t>(2, name.size() / 4)) + 1;
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string candidate = listing.GetFile(i);
    const size_t distance = EditDistance(name, candidate);
    if (distance < nearest && RegularFile(folder.empty() ? candidate : folder + "/" + candidate))
    {
      nearest = distance;
      best = candidate;
    }
  }
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

bool ReadText(const std::string& path, std::string& text)
{
  if (!RegularFile(path))
  {
    return false; // a FIFO would block for ever, /dev/zero never end
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return true;
}

const std::vector<Format>& Formats()
{
  static const std::vector<Format> formats = {
    { "OBJ", { "obj" }, ReadObj, false },
    { "glTF", { "gltf", "glb" }, ReadGltf, false },
    { "PLY", { "ply" }, ReadPly, false },
    { "VRML", { "wrl", "vrml" }, ReadVrml, false },
    { "assimp (IFC, FBX, DAE, 3DS and others)",
      { "ifc", "fbx", "dae", "3ds", "blend", "x3d", "lwo", "ase", "ms3d", "stl", "off", "x", "ac", "md5mesh" },
      ReadWithAssimp, true },
  };
  return formats;
}

const Format* FormatOf(const std::string& path)
{
  std::string extension = vtksys::SystemTools::GetFilenameLastExtension(path);
  extension = vtksys::SystemTools::LowerCase(extension.empty() ? extension : extension.substr(1));
  for (const Format& format : Formats())
  {
    if (std::find(format.Extensions.begin(), format.Extensions.end(), extension) != format.Extensions.end())
    {
      return &format;
    }
  }
  return nullptr;
}

std::string AllExtensions()
{
  std::string all;
  for (const Format& format : Formats())
  {
    for (const std::string& extension : format.Extensions)
    {
      all += (all.empty() ? "" : " ") + extension;
    }
  }
  return all;
}

namespace
{
/// The names and messages a file gave, as UTF-8 (a stray byte in a material name made the
/// whole error unreadable from Python: "OSError: None").
std::string WithValidText(const std::string& error, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  for (radiosity::ImportMaterial& material : raw.Materials)
  {
    material.Name = radiosity::ValidUtf8(material.Name);
  }
  for (std::vector<std::string>* texts : { &raw.ObjectNames, &warnings })
  {
    for (std::string& name : *texts)
    {
      name = radiosity::ValidUtf8(name);
    }
  }
  return radiosity::ValidUtf8(error);
}
}

std::string Read(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  if (!RegularFile(path))
  {
    return "'" + path + "' does not exist or is not a regular file" + NearestFile(path);
  }
  if (const Format* format = FormatOf(path))
  {
    return WithValidText(format->Read(path, raw, warnings), raw, warnings);
  }
  std::string known;
  for (const Format& format : Formats())
  {
    known += (known.empty() ? "" : ", ") + std::string(format.Name);
  }
  return "'" + path + "': the extension '" + vtksys::SystemTools::GetFilenameLastExtension(path) +
    "' is not a scene format this reader knows (" + known + "; extensions: " + AllExtensions() + ")";
}

int AppendPolygons(vtkPolyData* data, const vtkMatrix4x4* transform, int material, int object,
  radiosity::RawScene& raw)
{
  const int base = static_cast<int>(raw.Points.size());
  const bool mirrored = transform && vtkMatrix4x4::Determinant(&transform->Element[0][0]) < 0;
  const bool single = data->GetPoints() && data->GetPoints()->GetDataType() == VTK_FLOAT;
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
  {
    double x[4] = { 0, 0, 0, 1 };
    data->GetPoint(p, x);
    if (transform)
    {
      vtkMatrix4x4::MultiplyPoint(&transform->Element[0][0], x, x);
    }
    raw.Points.push_back({ x[0], x[1], x[2] });
    const double farthest = std::max({ std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) });
    raw.PointQuantum = single ? std::max(raw.PointQuantum, std::ldexp(farthest, -23)) : raw.PointQuantum;
  }
  auto each = [&](vtkCellArray* cells, bool strip) {
    auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType count = 0;
      const vtkIdType* ids = nullptr;
      iterator->GetCurrentCell(count, ids);
      (strip ? AddStrip : AddPolygon)(ids, count, base, material, object, mirrored, raw);
    }
  };
  each(data->GetPolys(), false);
  each(data->GetStrips(), true);
  return static_cast<int>(data->GetNumberOfVerts() + data->GetNumberOfLines());
}

TemporaryFolder::TemporaryFolder()
{
  const char* base = vtksys::SystemTools::GetEnv("TMPDIR");
  std::random_device random;
  this->Path = std::string(base && *base ? base : "/tmp") + "/relight-import-" + std::to_string(random()) +
    "-" + std::to_string(random());
  vtksys::SystemTools::MakeDirectory(this->Path);
}

TemporaryFolder::~TemporaryFolder()
{
  vtksys::SystemTools::RemoveADirectory(this->Path);
}


bool GlbBytes(const std::string& json, const std::string& binary, std::string& bytes)
{
  std::string text = json;
  text.append((4 - text.size() % 4) % 4, ' ');
  std::string data = binary;
  data.append((4 - data.size() % 4) % 4, '\0');
  const size_t total = 12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size());
  if (total > 0xFFFFFFFFull)
  {
    return false;
  }
  auto word = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  bytes = "glTF" + word(2) + word(static_cast<std::uint32_t>(total)) + word(static_cast<std::uint32_t>(text.size())) +
    "JSON" + text;
  if (!data.empty())
  {
    bytes += word(static_cast<std::uint32_t>(data.size())) + std::string("BIN\0", 4) + data;
  }
  return true;
}

double SrgbToLinear(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

radiosity::Vec3 MeanColor(vtkImageData* image)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  const int components = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || scalars->GetNumberOfTuples() == 0 || components < 1)
  {
    return { 1, 1, 1 };
  }
  // Integer textures (8 or 16 bit) hold sRGB codes; light adds up in linear values, so
  // average those. Grey (with or without alpha) counts for all three channels.
  const bool encoded = scalars->GetDataType() != VTK_FLOAT && scalars->GetDataType() != VTK_DOUBLE;
  const double full = encoded ? scalars->GetDataTypeMax() : 1.0;
  double sum[3] = { 0, 0, 0 };
  for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = scalars->GetComponent(t, components >= 3 ? c : 0) / full;
      sum[c] += encoded ? SrgbToLinear(v) : v;
    }
  }
  const double n = static_cast<double>(scalars->GetNumberOfTuples());
  return { sum[0] / n, sum[1] / n, sum[2] / n };
}

}

namespace SceneFiles
{

class ErrorCapture::Observer : public vtkCommand
{
public:
  static Observer* New() { return new Observer; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ErrorEvent && this->First.empty() && data)
    {
      // "ERROR: In file, line N\nclass (0x...): message" -> the message.
      std::string text = static_cast<const char*>(data);
      const size_t colon = text.find("): ");
      this->First = radiosity::Trimmed(colon == std::string::npos ? text : text.substr(colon + 3));
    }
  }
  std::string First;
};

ErrorCapture::ErrorCapture(vtkObject* reader)
  : Reader(reader)
  , Command(vtkSmartPointer<Observer>::New())
{
  // Warnings are observed too, and dropped: a reader's complaint becomes our one message.
  this->Tags[0] = reader->AddObserver(vtkCommand::ErrorEvent, this->Command);
  this->Tags[1] = reader->AddObserver(vtkCommand::WarningEvent, this->Command);
}

ErrorCapture::~ErrorCapture()
{
  this->Reader->RemoveObserver(this->Tags[0]);
  this->Reader->RemoveObserver(this->Tags[1]);
}

std::string ErrorCapture::Message() const
{
  return this->Command->First;
}

}
