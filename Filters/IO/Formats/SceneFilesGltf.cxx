// glTF 2.0 (.gltf, .glb) through VTK's document loader: node transforms applied,
// baseColorFactor (times the base color texture's mean) as the diffuse color, and
// emissiveFactor (times the emissive texture's mean) times KHR_materials_emissive_strength
// (read from the JSON: the loader skips that extension) as the emission.
#include "SceneFiles.h"
#include "SceneFilesErrors.h"
#include "SceneFilesGltfCheck.h"

#include "vtkGLTFDocumentLoader.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <vtk_nlohmannjson.h>
#include VTK_NLOHMANN_JSON(json.hpp)

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace SceneFiles
{
namespace
{

using Loader = vtkGLTFDocumentLoader;

/// A .gltf file's JSON, or a .glb file's JSON and binary chunks.
struct GltfParts
{
  std::string Json;
  std::string Binary;
  bool Glb = false;
  bool HasBinary = false;
};

GltfParts Split(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  GltfParts parts;
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0)
  {
    parts.Json = bytes;
    return parts;
  }
  parts.Glb = true;
  size_t at = 12;
  for (int chunk = 0; at + 8 <= bytes.size(); ++chunk)
  {
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + at, 4);
    const std::string type = bytes.substr(at + 4, 4);
    const std::string data = bytes.substr(at + 8, std::min<size_t>(length, bytes.size() - at - 8));
    // VTK's loader reads the first chunk as the JSON and the first binary chunk as buffer 0:
    // the checks must see the same ones.
    if (chunk == 0 && type == "JSON")
    {
      parts.Json = data;
    }
    else if (chunk > 0 && type == std::string("BIN\0", 4) && !parts.HasBinary)
    {
      parts.Binary = data;
      parts.HasBinary = true;
    }
    at += 8 + static_cast<size_t>(length);
  }
  return parts;
}

bool Has(const nlohmann::json& object, const char* key, bool (nlohmann::json::*kind)() const noexcept)
{
  return object.is_object() && object.contains(key) && (object[key].*kind)();
}

/// VTK 9.2's loader reads some keys without looking first, and a missing one ends the
/// whole process (an assertion in its JSON library). Where glTF 2.0 makes the key
/// optional (a material's pbrMetallicRoughness) it is added, and `patched` set; where the
/// key is required, the answer is what is missing.
std::string Prepare(nlohmann::json& document, bool& patched)
{
  using json = nlohmann::json;
  if (!Has(document, "asset", &json::is_object))
  {
    return "it has no asset object (not glTF 2.0)";
  }
  for (auto& material : document.value("materials", json::array()))
  {
    if (material.is_object() && !material.contains("pbrMetallicRoughness"))
    {
      patched = true;
    }
  }
  if (patched)
  {
    for (auto& material : document["materials"])
    {
      if (material.is_object() && !material.contains("pbrMetallicRoughness"))
      {
        material["pbrMetallicRoughness"] = json::object();
      }
    }
  }
  size_t m = 0;
  for (const auto& mesh : document.value("meshes", json::array()))
  {
    if (!Has(mesh, "primitives", &json::is_array))
    {
      return "mesh " + std::to_string(m) + " has no primitives";
    }
    for (const auto& primitive : mesh["primitives"])
    {
      if (!Has(primitive, "attributes", &json::is_object))
      {
        return "a primitive of mesh " + std::to_string(m) + " has no attributes";
      }
    }
    ++m;
  }
  for (const auto& camera : document.value("cameras", json::array()))
  {
    const std::string type = Has(camera, "type", &json::is_string) ? camera["type"].get<std::string>() : "";
    if ((type == "perspective" || type == "orthographic") && !Has(camera, type.c_str(), &json::is_object))
    {
      return "a camera has no " + type + " object";
    }
  }
  for (const auto& animation : document.value("animations", json::array()))
  {
    for (const auto& channel : animation.value("channels", json::array()))
    {
      if (!Has(channel, "target", &json::is_object))
      {
        return "an animation channel has no target";
      }
    }
  }
  return std::string();
}

/// Writes `document` where the loader can read it instead of `path`: URIs of files made
/// absolute (they were relative to `path`), and for a .glb the binary chunk kept.
std::string WritePatched(const std::string& path, const GltfParts& parts, nlohmann::json document,
  const std::string& folder)
{
  const std::string base = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path));
  for (const char* list : { "buffers", "images" })
  {
    if (!Has(document, list, &nlohmann::json::is_array))
    {
      continue;
    }
    for (auto& entry : document[list])
    {
      if (entry.is_object() && entry.contains("uri") && entry["uri"].is_string())
      {
        const std::string uri = entry["uri"].get<std::string>();
        if (uri.compare(0, 5, "data:") != 0)
        {
          entry["uri"] = vtksys::SystemTools::CollapseFullPath(uri, base);
        }
      }
    }
  }
  std::string text = document.dump();
  const std::string copy = folder + (parts.Glb ? "/scene.glb" : "/scene.gltf");
  std::ofstream out(copy, std::ios::binary);
  if (!parts.Glb)
  {
    out << text;
    return copy;
  }
  std::string bytes;
  GlbBytes(text, parts.Binary, bytes); // no larger than the file it came from
  out << bytes;
  return copy;
}

/// Each material's emissive strength (1 where the extension is absent).
std::vector<double> EmissiveStrengths(const nlohmann::json& document, size_t materials)
{
  std::vector<double> strength(materials, 1.0);
  if (!Has(document, "materials", &nlohmann::json::is_array))
  {
    return strength;
  }
  const auto& list = document["materials"];
  for (size_t m = 0; m < std::min(materials, list.size()); ++m)
  {
    const auto* value = &list[m];
    for (const char* key : { "extensions", "KHR_materials_emissive_strength", "emissiveStrength" })
    {
      value = value->is_object() && value->contains(key) ? &(*value)[key] : nullptr;
      if (!value)
      {
        break;
      }
    }
    if (value && value->is_number())
    {
      strength[m] = value->get<double>();
    }
  }
  return strength;
}

radiosity::Vec3 Rgb(const std::vector<double>& factor, const radiosity::Vec3& otherwise)
{
  return factor.size() >= 3 ? radiosity::Vec3{ factor[0], factor[1], factor[2] } : otherwise;
}

/// The mean linear color of a material's texture, white where there is none (glTF
/// multiplies each factor by its texture).
radiosity::Vec3 TextureMean(const Loader::Model& model, int texture)
{
  if (texture < 0 || texture >= static_cast<int>(model.Textures.size()))
  {
    return { 1, 1, 1 };
  }
  const int image = model.Textures[texture].Source;
  return image >= 0 && image < static_cast<int>(model.Images.size()) ? MeanColor(model.Images[image].ImageData)
                                                                      : radiosity::Vec3{ 1, 1, 1 };
}

void ReadMaterials(const nlohmann::json& document, const Loader::Model& model, radiosity::RawScene& raw)
{
  const std::vector<double> strength = EmissiveStrengths(document, model.Materials.size());
  for (size_t m = 0; m < model.Materials.size(); ++m)
  {
    const Loader::Material& source = model.Materials[m];
    radiosity::ImportMaterial material;
    material.Name = source.Name.empty() ? "material " + std::to_string(m) : source.Name;
    // glTF's default base color is white. A texture counts by its mean: radiosity holds one
    // color per element (an emissive texture's dark parts dim the lamp, as they would).
    material.Diffuse = radiosity::Times(Rgb(source.PbrMetallicRoughness.BaseColorFactor, { 1, 1, 1 }),
      TextureMean(model, source.PbrMetallicRoughness.BaseColorTexture.Index));
    material.Emissive = radiosity::Times(Rgb(source.EmissiveFactor, {}), TextureMean(model, source.EmissiveTexture.Index)) * strength[m];
    raw.Materials.push_back(material);
  }
}

/// Appends the meshes of node `n` and its children, placed by their global transforms.
int AppendNode(const Loader::Model& model, int n, radiosity::RawScene& raw, int depth)
{
  if (n < 0 || n >= static_cast<int>(model.Nodes.size()) || depth > 256)
  {
    return 0;
  }
  const Loader::Node& node = model.Nodes[n];
  int skipped = 0;
  if (node.Mesh >= 0 && node.Mesh < static_cast<int>(model.Meshes.size()))
  {
    const Loader::Mesh& mesh = model.Meshes[node.Mesh];
    const int object = static_cast<int>(raw.ObjectNames.size());
    raw.ObjectNames.push_back(!node.Name.empty() ? node.Name : !mesh.Name.empty() ? mesh.Name : "node " + std::to_string(n));
    for (const Loader::Primitive& primitive : mesh.Primitives)
    {
      if (primitive.Geometry)
      {
        skipped += AppendPolygons(primitive.Geometry, node.GlobalTransform, primitive.Material, object, raw);
      }
    }
  }
  for (int child : node.Children)
  {
    skipped += AppendNode(model, child, raw, depth + 1);
  }
  return skipped;
}

/// The first extension the file requires that the loader does not read (its data, Draco
/// meshes for one, would not be there), said first.
std::string Unsupported(const nlohmann::json& document, const std::vector<std::string>& supported)
{
  if (!Has(document, "extensionsRequired", &nlohmann::json::is_array))
  {
    return std::string();
  }
  for (const auto& name : document["extensionsRequired"])
  {
    const std::string extension = name.is_string() ? name.get<std::string>() : std::string("?");
    if (std::find(supported.begin(), supported.end(), extension) == supported.end())
    {
      return "it requires the extension " + extension + ", which VTK's glTF loader does not read";
    }
  }
  return std::string();
}

/// VTK's loader leaves out an entry it cannot read (an accessor whose min has the wrong
/// size, a node with a matrix and a skin...), which shifts every later index onto other
/// entries: then the file is refused, naming the first list that lost entries.
std::string DroppedEntries(const nlohmann::json& document, const Loader::Model& model)
{
  const std::pair<const char*, size_t> lists[] = { { "accessors", model.Accessors.size() },
    { "animations", model.Animations.size() }, { "bufferViews", model.BufferViews.size() },
    { "cameras", model.Cameras.size() }, { "images", model.Images.size() }, { "materials", model.Materials.size() },
    { "meshes", model.Meshes.size() }, { "nodes", model.Nodes.size() }, { "samplers", model.Samplers.size() },
    { "scenes", model.Scenes.size() }, { "skins", model.Skins.size() }, { "textures", model.Textures.size() } };
  for (const auto& list : lists)
  {
    const size_t written = Has(document, list.first, &nlohmann::json::is_array) ? document[list.first].size() : 0;
    if (written != list.second)
    {
      return "VTK's glTF loader could read " + std::to_string(list.second) + " of its " + std::to_string(written) + " " +
        list.first + " (one it cannot read would shift the others)";
    }
  }
  return std::string();
}

} // namespace

std::string ReadGltf(const std::string& path, radiosity::RawScene& raw, std::vector<std::string>& warnings)
{
  const GltfParts parts = Split(path);
  nlohmann::json document = nlohmann::json::parse(parts.Json, nullptr, false);
  bool patched = false;
  const std::string invalid = document.is_discarded() ? "it is not JSON" : Prepare(document, patched);
  if (!invalid.empty())
  {
    return "'" + path + "' could not be read as glTF: " + invalid;
  }
  vtkNew<Loader> loader;
  std::string unsafe = Unsupported(document, loader->GetSupportedExtensions());
  if (unsafe.empty())
  {
    unsafe =
      CheckGltfReferences(document, path, parts.Glb && parts.HasBinary ? static_cast<long long>(parts.Binary.size()) : -1);
  }
  if (!unsafe.empty())
  {
    return "'" + path + "' could not be read as glTF: " + unsafe;
  }
  const TemporaryFolder folder;
  const std::string readable = patched ? WritePatched(path, parts, document, folder.Path) : path;
  const ErrorCapture capture(loader);
  std::vector<char> binary;
  if (!loader->LoadModelMetaDataFromFile(readable))
  {
    return "'" + path + "' could not be read as glTF" +
      (capture.Message().empty() ? std::string() : " (" + capture.Message() + ")");
  }
  const std::string dropped = DroppedEntries(document, *loader->GetInternalModel());
  if (!dropped.empty())
  {
    return "'" + path + "' could not be read as glTF: " + dropped;
  }
  if ((parts.Glb && !loader->LoadFileBuffer(readable, binary)) || !loader->LoadModelData(binary) ||
    !loader->BuildModelVTKGeometry())
  {
    return "'" + path + "' could not be read as glTF" +
      (capture.Message().empty() ? std::string() : " (" + capture.Message() + ")");
  }
  loader->BuildGlobalTransforms();
  const Loader::Model& model = *loader->GetInternalModel();
  ReadMaterials(document, model, raw);
  int skipped = 0;
  if (model.Scenes.empty())
  {
    // No scene: every node that is no other node's child is a root (children come with it).
    std::vector<char> child(model.Nodes.size(), 0);
    for (const Loader::Node& node : model.Nodes)
    {
      for (int c : node.Children)
      {
        if (c >= 0 && c < static_cast<int>(child.size()))
        {
          child[c] = 1;
        }
      }
    }
    for (int n = 0; n < static_cast<int>(model.Nodes.size()); ++n)
    {
      skipped += child[n] ? 0 : AppendNode(model, n, raw, 0);
    }
  }
  else
  {
    const int scene = model.DefaultScene >= 0 && model.DefaultScene < static_cast<int>(model.Scenes.size())
      ? model.DefaultScene
      : 0;
    for (unsigned int n : model.Scenes[scene].Nodes)
    {
      skipped += AppendNode(model, static_cast<int>(n), raw, 0);
    }
  }
  if (skipped)
  {
    warnings.push_back(std::to_string(skipped) + " point and line primitives are not surfaces; left out");
  }
  return raw.NumberOfPolygons() ? std::string() : "'" + path + "' has no triangles";
}

}
