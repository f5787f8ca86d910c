// VRML97 through VTK's importer, which reads the geometry (IndexedFaceSet and the
// primitives), Transform and DEF/USE of shapes and coordinates. Its materials need help:
// - it keeps a Material's emissiveColor as the vtkProperty's ambient colour, whose default
//   is white, so a material naming no emissive colour would read as a white lamp;
// - it ignores USE of a Material or Appearance, leaving that shape a default property.
// So the file is read from a copy in which every USE of a DEF'd Material or Appearance is
// replaced by its definition, and every Material starts with VRML's own defaults
// (`emissiveColor 0 0 0 ambientIntensity 0.2`), which the colours the file gives replace.
// A shape with no Material keeps VTK's default property (ambient 0), and is read as an
// unlit surface of the default reflectance.
#include "SceneFiles.h"
#include "SceneFilesErrors.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkVRMLImporter.h"

#include <vtksys/SystemTools.hxx>

#include <fstream>
#include <map>
#include <regex>

namespace SceneFiles
{
namespace
{

/// Where the body `{ ... }` that starts at or after `from` ends (one past its brace).
size_t BodyEnd(const std::string& text, size_t from)
{
  size_t open = text.find('{', from);
  int depth = 0;
  for (size_t k = open; k < text.size(); ++k)
  {
    depth += text[k] == '{' ? 1 : text[k] == '}' ? -1 : 0;
    if (depth == 0)
    {
      return k + 1;
    }
  }
  return std::string::npos;
}

/// DEF'd Material and Appearance nodes: name -> "Type { ... }".
std::map<std::string, std::string> Definitions(const std::string& text)
{
  std::map<std::string, std::string> found;
  static const std::regex defined(R"(DEF\s+([^\s{}\[\]]+)\s+(Material|Appearance)\s*\{)");
  for (std::sregex_iterator m(text.begin(), text.end(), defined), end; m != end; ++m)
  {
    const size_t start = static_cast<size_t>(m->position(2));
    const size_t stop = BodyEnd(text, start);
    if (stop != std::string::npos)
    {
      found.emplace((*m)[1].str(), text.substr(start, stop - start));
    }
  }
  return found;
}

/// The copy VTK reads: USEs of materials and appearances written out, VRML's defaults first
/// in every Material.
std::string Prepared(const std::string& text, const std::map<std::string, std::string>& definitions)
{
  static const std::regex use(R"(\bUSE\s+([^\s{}\[\]]+))");
  std::string expanded;
  size_t last = 0;
  for (std::sregex_iterator m(text.begin(), text.end(), use), end; m != end; ++m)
  {
    const auto definition = definitions.find((*m)[1].str());
    if (definition != definitions.end())
    {
      expanded += text.substr(last, static_cast<size_t>(m->position()) - last) + definition->second;
      last = static_cast<size_t>(m->position() + m->length());
    }
  }
  expanded += text.substr(last);
  static const std::regex material(R"(\bMaterial(\s*)\{)");
  return std::regex_replace(expanded, material, "Material$1{ emissiveColor 0 0 0 ambientIntensity 0.2 ");
}

/// The three numbers after `field` in a node's text, or `otherwise`.
radiosity::Vec3 Colour(const std::string& node, const std::string& field, const radiosity::Vec3& otherwise)
{
  const std::regex value("\\b" + field + R"(\s+([-+0-9.eE]+)[\s,]+([-+0-9.eE]+)[\s,]+([-+0-9.eE]+))");
  std::smatch m;
  if (!std::regex_search(node, m, value))
  {
    return otherwise;
  }
  return { std::stod(m[1].str()), std::stod(m[2].str()), std::stod(m[3].str()) };
}

/// The material of an actor's property, one per distinct colour pair; named after the
/// first DEF'd Material of those colours, if any.
int MaterialOf(vtkProperty* property, const std::map<std::string, std::string>& definitions,
  std::map<std::pair<std::string, std::string>, int>& seen, radiosity::RawScene& raw, int& unlit)
{
  radiosity::ImportMaterial material;
  const double* diffuse = property->GetDiffuseColor();
  const double* emissive = property->GetAmbientColor();
  const bool none = property->GetAmbient() == 0; // VTK's default: the shape had no Material
  unlit += none ? 1 : 0;
  if (!none)
  {
    material.Diffuse = { diffuse[0], diffuse[1], diffuse[2] };
    material.Emissive = { emissive[0], emissive[1], emissive[2] };
  }
  auto text = [](const radiosity::Vec3& v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z);
  };
  const auto key = std::make_pair(text(material.Diffuse), text(material.Emissive));
  const auto known = seen.find(key);
  if (known != seen.end())
  {
    return known->second;
  }
  material.Name = "Material" + std::to_string(raw.materials.size() + 1);
  for (const auto& definition : definitions)
  {
    const std::string& node = definition.second;
    if (node.compare(0, 8, "Material") == 0 && !none &&
      text(Colour(node, "diffuseColor", { 0.8, 0.8, 0.8 })) == key.first &&
      text(Colour(node, "emissiveColor", { 0, 0, 0 })) == key.second)
    {
      material.Name = definition.first;
      break;
    }
  }
  raw.materials.push_back(material);
  return seen[key] = static_cast<int>(raw.materials.size()) - 1;
}

} // namespace

std::string ReadVrml(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  std::string text;
  if (!ReadText(path, text))
  {
    return "cannot read '" + path + "'";
  }
  if (text.compare(0, 10, "#VRML V2.0") != 0)
  {
    return "'" + path + "' is not VRML97 (its first line must be '#VRML V2.0 utf8'; VRML 1.0 is not read)";
  }
  const std::map<std::string, std::string> definitions = Definitions(text);
  TemporaryFolder folder;
  const std::string copy = folder.Path + "/scene.wrl";
  {
    std::ofstream out(copy, std::ios::binary);
    out << Prepared(text, definitions);
    if (!out)
    {
      return "cannot write a working copy of '" + path + "' in " + folder.Path;
    }
  }
  vtkNew<vtkVRMLImporter> importer;
  vtkNew<vtkRenderWindow> window; // holds the importer's actors; it is never shown
  importer->SetFileName(copy.c_str());
  importer->SetRenderWindow(window);
  const ErrorCapture errors(importer);
  importer->Update();
  if (!errors.Message().empty())
  {
    return "'" + path + "': " + errors.Message();
  }
  std::map<std::pair<std::string, std::string>, int> seen;
  int shapes = 0, skipped = 0, unlit = 0;
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* renderer = renderers->GetNextItem())
  {
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
    {
      auto* data = actor->GetMapper() ? vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputAsDataSet()) : nullptr;
      if (!data)
      {
        continue;
      }
      raw.objectNames.push_back("Shape" + std::to_string(++shapes));
      const int material = MaterialOf(actor->GetProperty(), definitions, seen, raw, unlit);
      skipped += AppendPolygons(data, actor->GetMatrix(), material, static_cast<int>(raw.objectNames.size()) - 1, raw);
    }
  }
  if (unlit > 0)
  {
    warnings.push_back(std::to_string(unlit) + " shapes in '" + path +
      "' have no Material: read as unlit, of the default reflectance (0.8)");
  }
  if (skipped > 0)
  {
    warnings.push_back(std::to_string(skipped) + " lines or points in '" + path + "' left out (not surfaces)");
  }
  return raw.NumberOfPolygons() > 0 ? "" : "'" + path + "' holds no polygons";
}

} // namespace SceneFiles
