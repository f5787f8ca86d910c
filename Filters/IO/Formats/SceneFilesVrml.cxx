// VRML97 through VTK's importer, which reads the geometry (IndexedFaceSet and the
// primitives), Transform and DEF/USE of shapes and coordinates. Its materials need help:
// - it ignores USE of a Material or Appearance, leaving that shape a default property;
// - it starts every Material from vtkProperty's defaults (white diffuse, white ambient)
//   rather than VRML's (0.8 diffuse, black emissive), and keeps emissiveColor as the
//   ambient color, so a material naming no emissive color would read as a white lamp;
// - it does not say which Material a shape's property came from.
// So the file is read from a copy in which comments are gone, every USE of a DEF'd
// Material or Appearance is replaced by that definition (the latest before it, as VRML
// resolves names), and every Material starts with VRML's defaults and ends with a tag in
// its specularColor (which radiosity does not use) naming the Material it was. A shape
// with no Material has no tag, and is read as an unlit surface of the default reflectance.
#include "SceneFiles.h"
#include "SceneFilesErrors.h"
#include "Base/Text.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkMapper.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkVRMLImporter.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <cmath>
#include <regex>
#include <vector>

namespace SceneFiles
{
namespace
{

/// Whether text[k] opens or closes a string: a '"' after an even number of backslashes
/// ("C:\\" ends where it seems to).
bool IsQuote(const std::string& text, size_t k)
{
  size_t backslashes = 0;
  while (backslashes < k && text[k - 1 - backslashes] == '\\')
  {
    ++backslashes;
  }
  return text[k] == '"' && backslashes % 2 == 0;
}

/// The text without its `#` comments and with its commas as spaces (strings kept whole):
/// VRML97 counts commas as white space, and VTK's parser crashed on "4,0,4".
std::string WithoutComments(const std::string& text)
{
  std::string out;
  bool quoted = false;
  for (size_t k = 0; k < text.size(); ++k)
  {
    if (!quoted && text[k] == '#')
    {
      k = text.find('\n', k);
      if (k == std::string::npos)
      {
        break;
      }
    }
    quoted = IsQuote(text, k) ? !quoted : quoted;
    out += !quoted && text[k] == ',' ? ' ' : text[k];
  }
  return out;
}

/// Each run of white space outside strings as one space (one line end if it held any):
/// the Expander's std::regex recurses once per character it matches, and a long run of
/// spaces overflowed the stack (words are at most a thousand characters: CheckVrmlText).
std::string Condensed(const std::string& text)
{
  std::string out;
  bool quoted = false, space = false, newline = false;
  for (size_t k = 0; k < text.size(); ++k)
  {
    const char c = text[k];
    if (!quoted && std::isspace(static_cast<unsigned char>(c)))
    {
      space = true;
      newline = newline || c == '\n';
      continue;
    }
    if (space)
    {
      out += newline ? '\n' : ' ';
      space = newline = false;
    }
    quoted = IsQuote(text, k) ? !quoted : quoted;
    out += c;
  }
  return out;
}

/// One past the `}` that closes the `{` at `open` (strings skipped), or npos.
size_t BodyEnd(const std::string& text, size_t open)
{
  int depth = 0;
  bool quoted = false;
  for (size_t k = open; k < text.size(); ++k)
  {
    quoted = IsQuote(text, k) ? !quoted : quoted;
    depth += quoted ? 0 : text[k] == '{' ? 1 : text[k] == '}' ? -1 : 0;
    if (depth == 0)
    {
      return k + 1;
    }
  }
  return std::string::npos;
}

/// The Materials of a file: their DEF names ("" for none), by tag.
using MaterialTags = std::vector<std::string>;

/// The specularColor that tags Material `index`: green and blue mark it as ours.
std::string Tag(size_t index)
{
  return " specularColor " + std::to_string(index + 1) + " 0.125 0.375 ";
}

/// The copy VTK reads (see the top of this file), expanding DEFs and USEs in order.
class Expander
{
public:
  explicit Expander(MaterialTags& tags)
    : Tags(tags)
  {
  }

  std::string Expand(const std::string& text)
  {
    static const std::regex node(
      R"(DEF\s+([^\s{}\[\]"]+)\s+(Material|Appearance)\s*\{|\b(Material)\s*\{|\bUSE\s+([^\s{}\[\]"]+))");
    std::string out;
    size_t at = 0;
    std::smatch m;
    while (std::regex_search(text.begin() + static_cast<std::ptrdiff_t>(at), text.end(), m, node))
    {
      const size_t start = at + static_cast<size_t>(m.position());
      out += text.substr(at, start - at);
      at = start + static_cast<size_t>(m.length());
      if (m[4].matched) // USE: the latest definition of that name, if it is one of ours
      {
        const auto definition = Definitions.find(m[4].str());
        out += definition != Definitions.end() ? definition->second : m.str();
        continue;
      }
      const size_t open = at - 1, close = BodyEnd(text, open);
      if (close == std::string::npos)
      {
        out += text.substr(start);
        return out; // unbalanced: VTK's parser will say where
      }
      const std::string name = m[1].matched ? m[1].str() : "";
      const std::string inner = Expand(text.substr(open + 1, close - open - 2));
      const bool material = m[2].str() == "Material" || m[3].matched;
      std::string body = material ? "Material { emissiveColor 0 0 0 ambientIntensity 0.2 diffuseColor 0.8 0.8 0.8 " + inner +
          Tag(Tags.size()) + "}"
                                  : "Appearance {" + inner + "}";
      if (material)
      {
        Tags.push_back(name);
      }
      if (!name.empty())
      {
        Definitions[name] = body;
        body = "DEF " + name + " " + body;
      }
      out += body;
      at = close;
    }
    return out + text.substr(at);
  }

private:
  MaterialTags& Tags;
  std::map<std::string, std::string> Definitions;
};

/// The Material a property came from (its tag), or -1 for a shape without one.
int TagOf(vtkProperty* property, size_t count)
{
  const double* tag = property->GetSpecularColor();
  const long index = std::lround(tag[0]) - 1;
  return tag[1] == 0.125 && tag[2] == 0.375 && index >= 0 && static_cast<size_t>(index) < count
    ? static_cast<int>(index)
    : -1;
}

/// The material of an actor's property: one per Material of the file (a USEd one is the
/// same), named after its DEF if it has one; and one for all shapes without a Material.
int MaterialOf(vtkProperty* property, const MaterialTags& tags, std::map<int, int>& seen,
  radiosity::RawScene& raw, int& unlit)
{
  const int tag = TagOf(property, tags.size());
  unlit += tag < 0 ? 1 : 0;
  const auto known = seen.find(tag);
  if (known != seen.end())
  {
    return known->second;
  }
  radiosity::ImportMaterial material; // VRML's defaults, as for a shape with no Material
  if (tag >= 0)
  {
    const double* diffuse = property->GetDiffuseColor();
    const double* emissive = property->GetAmbientColor();
    material.Diffuse = { diffuse[0], diffuse[1], diffuse[2] };
    material.Emissive = { emissive[0], emissive[1], emissive[2] };
  }
  const bool named = tag >= 0 && !tags[tag].empty();
  material.Name = named ? tags[tag] : "Material" + std::to_string(raw.Materials.size() + 1);
  raw.Materials.push_back(material);
  return seen[tag] = static_cast<int>(raw.Materials.size()) - 1;
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
  const std::string uncommented = WithoutComments(text);
  const std::string problem = CheckVrmlText(uncommented);
  if (!problem.empty())
  {
    return "'" + path + "', " + problem;
  }
  MaterialTags tags;
  const std::string prepared = "#VRML V2.0 utf8\n" + Expander(tags).Expand(Condensed(uncommented));
  TemporaryFolder folder;
  const std::string copy = folder.Path + "/scene.wrl";
  {
    std::ofstream out(copy, std::ios::binary);
    out << prepared;
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
  std::map<int, int> seen;
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
      raw.ObjectNames.push_back("Shape" + std::to_string(++shapes));
      const int material = MaterialOf(actor->GetProperty(), tags, seen, raw, unlit);
      skipped += AppendPolygons(data, actor->GetMatrix(), material, static_cast<int>(raw.ObjectNames.size()) - 1, raw);
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
