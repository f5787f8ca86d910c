// Wavefront OBJ + MTL: the text through the core's parsers (see Wavefront.h for why not
// vtkOBJReader), diffuse textures through VTK's image readers.
#include "SceneFiles.h"

#include "Import/Wavefront.h"

#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkSmartPointer.h"

#include <vtksys/Directory.hxx>
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

/// The file in `folder` named `name`, else named so up to case (a 3DS file asks for
/// IMAGE1.JPG beside IMAGE1.jpg: names from DOS and Windows); empty when there is none.
std::string AnyCase(const std::string& name, const std::string& folder)
{
  vtksys::Directory listing;
  if (vtksys::SystemTools::FileExists(folder + "/" + name, true) || !listing.Load(folder))
  {
    return vtksys::SystemTools::FileExists(folder + "/" + name, true) ? folder + "/" + name : std::string();
  }
  const std::string wanted = vtksys::SystemTools::LowerCase(name);
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string file = folder + "/" + listing.GetFile(i);
    if (vtksys::SystemTools::LowerCase(listing.GetFile(i)) == wanted && vtksys::SystemTools::FileExists(file, true))
    {
      return file;
    }
  }
  return std::string();
}

/// Where a texture named in a material library is, its name in any case: at its path from
/// `folder` (Windows' backslashes as slashes: FBX and 3DS files carry them; a leading one
/// taken as relative, as in "\\..\\maps\\x.jpg"), else in `folder` (models often name a path
/// on their author's machine), else in its last folder beside `folder` (a model's FBX and
/// OBJ folders sharing textures); empty when none is a file.
std::string FindTexture(const std::string& named, const std::string& folder)
{
  std::string path = named;
  std::replace(path.begin(), path.end(), '\\', '/');
  const std::string name = vtksys::SystemTools::GetFilenameName(path);
  const std::string last = vtksys::SystemTools::GetFilenameName(vtksys::SystemTools::GetFilenamePath(path));
  const size_t start = path.find_first_not_of('/');
  const std::string relative = start == std::string::npos ? path : path.substr(start);
  for (const std::string& place : { vtksys::SystemTools::CollapseFullPath(path, folder),
         vtksys::SystemTools::CollapseFullPath(relative, folder), folder + "/" + name,
         vtksys::SystemTools::GetFilenamePath(folder) + "/" + last + "/" + name })
  {
    const std::string file = name.empty() ? std::string() : AnyCase(name, vtksys::SystemTools::GetFilenamePath(place));
    if (!file.empty())
    {
      return file;
    }
  }
  return std::string();
}

/// A white diffuse color (all channels 1) would reflect all light that reaches it, and
/// none is meant: it is what a textured material or an exporter's placeholder leaves.
bool White(const radiosity::Vec3& diffuse)
{
  return diffuse.x >= 1 && diffuse.y >= 1 && diffuse.z >= 1;
}

/// `color` times the mean color of the texture `named` (glTF and MTL multiply the two), or
/// false and why there is none.
bool TimesTexture(const std::string& folder, const std::string& named, radiosity::Vec3& color, std::string& why)
{
  const std::string file = FindTexture(named, folder);
  if (file.empty()) // not handed to VTK's image readers, which log an error of their own
  {
    why = "is not in '" + folder + "'";
    return false;
  }
  vtkSmartPointer<vtkImageReader2> reader =
    vtk::TakeSmartPointer(vtkImageReader2Factory::CreateImageReader2(file.c_str()));
  if (!reader)
  {
    why = "could not be read";
    return false;
  }
  reader->SetFileName(file.c_str());
  reader->Update();
  color = radiosity::Times(color, MeanColor(reader->GetOutput()));
  return true;
}

/// The diffuse color times its texture's mean color, where the texture can be read; else
/// the diffuse color alone, 0.8 where that is white.
void ApplyTexture(const std::string& folder, radiosity::ImportMaterial& m, std::vector<std::string>& warnings)
{
  std::string why;
  if (TimesTexture(folder, m.DiffuseTexture, m.Diffuse, why))
  {
    return;
  }
  const bool white = White(m.Diffuse);
  m.Diffuse = white ? radiosity::Vec3{ 0.8, 0.8, 0.8 } : m.Diffuse;
  warnings.push_back("the texture '" + m.DiffuseTexture + "' of material '" + m.Name + "' " + why +
    (white ? "; its Kd is white (it would reflect all light): reflectance 0.8" : "; its Kd alone is used"));
}

/// The emitted color times its texture's mean (a lamp's dark parts dim it), where the
/// texture can be read; else the emitted color alone.
void ApplyEmissiveTexture(const std::string& folder, radiosity::ImportMaterial& m, std::vector<std::string>& warnings)
{
  std::string why;
  if (!TimesTexture(folder, m.EmissiveTexture, m.Emissive, why))
  {
    warnings.push_back("the emissive texture '" + m.EmissiveTexture + "' of material '" + m.Name + "' " + why +
      "; its Ke alone is used");
  }
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
  for (radiosity::ImportMaterial& used : raw.Materials)
  {
    const auto found = std::find_if(definitions.begin(), definitions.end(),
      [&](const radiosity::ImportMaterial& m) { return m.Name == used.Name; });
    if (found == definitions.end())
    {
      warnings.push_back("material '" + used.Name + "' is used but defined in no material library: reflectance 0.8");
      continue;
    }
    used = *found;
    if (!used.EmissiveTexture.empty())
    {
      ApplyEmissiveTexture(textureFolder, used, warnings);
    }
    if (!used.DiffuseTexture.empty())
    {
      ApplyTexture(textureFolder, used, warnings);
    }
    else if (used.Name == "DefaultMaterial" && White(used.Diffuse)) // assimp's, for a file without materials
    {
      used.Diffuse = { 0.8, 0.8, 0.8 };
      warnings.push_back("the file gives no material (assimp's default is white, which would reflect all light): "
                         "reflectance 0.8");
    }
  }
  return raw.NumberOfPolygons() ? std::string() : "'" + path + "' has no faces";
}

}
