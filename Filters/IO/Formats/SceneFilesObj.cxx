// Wavefront OBJ + MTL: the text through the core's parsers (see Wavefront.h for why not
// vtkOBJReader), diffuse textures through VTK's image readers.
#include "SceneFiles.h"

#include "Import/Wavefront.h"

#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkSmartPointer.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace SceneFiles
{
namespace
{

/// The definitions in every `mtllib` the OBJ names, looked up beside the OBJ.
std::string ReadLibraries(const std::string& path, const std::vector<std::string>& libraries,
  std::vector<radiosity::ImportMaterial>& definitions)
{
  const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
  for (const std::string& library : libraries)
  {
    const std::string file = vtksys::SystemTools::CollapseFullPath(library, folder);
    std::string text;
    if (!ReadText(file, text))
    {
      return "'" + path + "' uses the material library '" + library + "', which is missing or not a regular file (looked for " + file + ")";
    }
    const std::string error = radiosity::ParseMtl(text, definitions);
    if (!error.empty())
    {
      return "'" + path + "', material library '" + library + "', " + error;
    }
  }
  return std::string();
}

/// Where a texture named in a material library is: its path from `folder` (with Windows'
/// backslashes as slashes: FBX and 3DS files carry them), else its file name in `folder`
/// (models often name a path on their author's machine); empty when neither is a file.
std::string FindTexture(const std::string& named, const std::string& folder)
{
  std::string path = named;
  std::replace(path.begin(), path.end(), '\\', '/');
  for (const std::string& file : { vtksys::SystemTools::CollapseFullPath(path, folder),
         vtksys::SystemTools::CollapseFullPath(vtksys::SystemTools::GetFilenameName(path), folder) })
  {
    if (vtksys::SystemTools::FileExists(file, true))
    {
      return file;
    }
  }
  return std::string();
}

/// The diffuse color times its texture's mean color, where the texture can be read.
void ApplyTexture(const std::string& folder, radiosity::ImportMaterial& m, std::vector<std::string>& warnings)
{
  const std::string file = FindTexture(m.DiffuseTexture, folder);
  if (file.empty()) // not handed to VTK's image readers, which log an error of their own
  {
    warnings.push_back("the texture '" + m.DiffuseTexture + "' of material '" + m.Name + "' is not in '" + folder +
      "'; its Kd alone is used");
    return;
  }
  vtkSmartPointer<vtkImageReader2> reader =
    vtk::TakeSmartPointer(vtkImageReader2Factory::CreateImageReader2(file.c_str()));
  if (!reader)
  {
    warnings.push_back("the texture '" + m.DiffuseTexture + "' of material '" + m.Name +
      "' could not be read; its Kd alone is used");
    return;
  }
  reader->SetFileName(file.c_str());
  reader->Update();
  const radiosity::Vec3 mean = MeanColor(reader->GetOutput());
  m.Diffuse = { m.Diffuse.x * mean.x, m.Diffuse.y * mean.y, m.Diffuse.z * mean.z };
}

} // namespace

std::string ReadObj(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  return ReadObjTexturedFrom(path, vtksys::SystemTools::GetFilenamePath(path), raw, warnings);
}

std::string ReadObjTexturedFrom(const std::string& path, const std::string& textureFolder, radiosity::RawScene& raw,
  std::vector<std::string>& warnings)
{
  std::string text;
  if (!ReadText(path, text))
  {
    return "'" + path + "' cannot be opened";
  }
  std::vector<std::string> libraries;
  std::string error = radiosity::ParseObj(text, raw, libraries);
  if (!error.empty())
  {
    return "'" + path + "', " + error;
  }
  std::vector<radiosity::ImportMaterial> definitions;
  if (!(error = ReadLibraries(path, libraries, definitions)).empty())
  {
    return error;
  }
  for (radiosity::ImportMaterial& used : raw.materials)
  {
    const auto found = std::find_if(definitions.begin(), definitions.end(),
      [&](const radiosity::ImportMaterial& m) { return m.Name == used.Name; });
    if (found == definitions.end())
    {
      warnings.push_back("material '" + used.Name + "' is used but defined in no material library: reflectance 0.8");
      continue;
    }
    used = *found;
    if (!used.DiffuseTexture.empty())
    {
      ApplyTexture(textureFolder, used, warnings);
    }
  }
  return raw.NumberOfPolygons() ? std::string() : "'" + path + "' has no faces";
}

}
