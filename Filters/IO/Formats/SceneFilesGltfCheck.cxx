// What a glTF file says about its own data, held against that data before VTK's loader
// trusts it: an index past a list, a range past its buffer, a file outside the model's
// folder or a node graph with a cycle crash that loader (or read what is not the model's).
#include "SceneFilesGltfCheck.h"
#include "SceneFiles.h"

#include <vtksys/SystemTools.hxx>

#include <vector>

namespace SceneFiles
{
namespace
{
using json = nlohmann::json;

/// The list `key` of the document (empty when absent or not a list).
const json& List(const json& document, const char* key)
{
  static const json empty = json::array();
  return document.is_object() && document.contains(key) && document[key].is_array() ? document[key] : empty;
}

/// object[key] as a whole number, `otherwise` when absent; -1 when present and not one.
long long Whole(const json& object, const char* key, long long otherwise)
{
  if (!object.is_object() || !object.contains(key))
  {
    return otherwise;
  }
  const json& v = object[key];
  // VTK's loader keeps these in int: a larger one would wrap there (and overflow sums here).
  const bool whole = v.is_number_unsigned() ? v.get<unsigned long long>() <= 2147483647ULL
                                            : v.is_number_integer() && v.get<long long>() <= 2147483647LL;
  return whole ? v.get<long long>() : -1;
}

/// object[key] as text, empty when absent or not text.
std::string Text(const json& object, const char* key)
{
  return object.is_object() && object.contains(key) && object[key].is_string() ? object[key].get<std::string>()
                                                                                : std::string();
}

constexpr int kDeepestNode = 1024;

std::string Named(const char* list, size_t i)
{
  return std::string(list) + " " + std::to_string(i);
}

/// Empty when `index` names an item of `list`; otherwise what is wrong, said of `owner`.
std::string Refers(const json& document, const std::string& owner, const char* field, long long index, const char* list)
{
  if (index >= 0 && index < static_cast<long long>(List(document, list).size()))
  {
    return std::string();
  }
  const std::string plural = list;
  const std::string one = plural.compare(plural.size() - 2, 2, "es") == 0 && plural != "images" && plural != "scenes"
    ? plural.substr(0, plural.size() - 2)
    : plural.substr(0, plural.size() - 1);
  return owner + "'s " + field + " names " + one + " " + std::to_string(index) + ", and there are " +
    std::to_string(List(document, list).size()) + " " + plural;
}

/// Bytes behind a data: URI's base64 text.
long long DataUriBytes(const std::string& uri)
{
  const size_t comma = uri.find(',');
  if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
  {
    return -1;
  }
  const std::string text = uri.substr(comma + 1);
  const size_t padding = text.size() - std::min(text.size(), text.find_last_not_of('=') + 1);
  return static_cast<long long>(text.size() / 4 * 3) - static_cast<long long>(padding);
}

/// Empty when `uri` is a data: URI or names a regular file of at least `bytes` bytes in
/// the model's folder or below it; otherwise why not. `size` gets the bytes behind it.
std::string LocalFile(const std::string& uri, const std::string& folder, long long& size)
{
  if (uri.compare(0, 5, "data:") == 0)
  {
    size = DataUriBytes(uri);
    return size < 0 ? "is a data URI that is not base64" : std::string();
  }
  std::vector<std::string> parts;
  vtksys::SystemTools::SplitPath(uri, parts);
  const bool outside = uri.find("://") != std::string::npos || !parts.empty() && !parts[0].empty();
  for (const std::string& part : parts)
  {
    if (part == ".." || outside)
    {
      return "'" + uri + "' is not in the model's folder";
    }
  }
  const std::string path = folder + "/" + uri;
  if (!vtksys::SystemTools::PathExists(path))
  {
    return "'" + uri + "' is missing";
  }
  if (!RegularFile(path))
  {
    return "'" + uri + "' is not a regular file";
  }
  size = static_cast<long long>(vtksys::SystemTools::FileLength(path));
  return std::string();
}

std::string CheckBuffers(const json& document, const std::string& folder, long long glbBinary)
{
  const json& buffers = List(document, "buffers");
  for (size_t i = 0; i < buffers.size(); ++i)
  {
    const json& buffer = buffers[i];
    const long long length = Whole(buffer, "byteLength", -1);
    long long held = glbBinary;
    std::string error;
    if (length < 0)
    {
      error = "has no byteLength";
    }
    else if (buffer.is_object() && buffer.contains("uri"))
    {
      error = buffer["uri"].is_string() ? LocalFile(buffer["uri"].get<std::string>(), folder, held) : "has a uri that is not text";
    }
    else if (i > 0 || glbBinary < 0)
    {
      error = "has no uri (only a .glb's first buffer may go without)";
    }
    // VTK's loader drops a buffer whose size is not the one claimed (a .glb's binary chunk
    // may be padded by up to 3 bytes): later indices would then miss it.
    const bool padded = glbBinary >= 0 && i == 0 && !(buffer.is_object() && buffer.contains("uri"));
    if (error.empty() && (held < length || held > length + (padded ? 3 : 0)))
    {
      error = "claims " + std::to_string(length) + " bytes and holds " + std::to_string(held) +
        (held < length ? " (the file is cut short, or not the one the model was written with)" : "");
    }
    if (error.empty() && glbBinary >= 0 && i == 0 && buffer.is_object() && buffer.contains("uri"))
    {
      error = "has a uri, and VTK's loader reads the .glb's binary chunk for it";
    }
    if (!error.empty())
    {
      return Named("buffer", i) + " " + error;
    }
  }
  return std::string();
}

std::string CheckViews(const json& document)
{
  const json& views = List(document, "bufferViews");
  for (size_t i = 0; i < views.size(); ++i)
  {
    const json& view = views[i];
    const long long buffer = Whole(view, "buffer", -1);
    std::string error = Refers(document, Named("bufferView", i), "buffer", buffer, "buffers");
    if (!error.empty())
    {
      return error;
    }
    const long long offset = Whole(view, "byteOffset", 0), length = Whole(view, "byteLength", -1);
    const long long held = Whole(List(document, "buffers")[buffer], "byteLength", 0);
    const long long stride = Whole(view, "byteStride", 4);
    if (offset < 0 || length < 0)
    {
      return Named("bufferView", i) + " has a byteOffset or byteLength that is not a whole number below 2^31";
    }
    if (offset + length > held || stride < 1 || stride > 252)
    {
      return Named("bufferView", i) + " (offset " + std::to_string(offset) + ", length " + std::to_string(length) +
        ", stride " + std::to_string(stride) + ") does not fit its buffer of " + std::to_string(held) + " bytes";
    }
  }
  return std::string();
}

long long ComponentBytes(long long type)
{
  switch (type)
  {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      return 0;
  }
}

long long Components(const std::string& type)
{
  static const std::pair<const char*, long long> types[] = { { "SCALAR", 1 }, { "VEC2", 2 }, { "VEC3", 3 },
    { "VEC4", 4 }, { "MAT2", 4 }, { "MAT3", 9 }, { "MAT4", 16 } };
  for (const auto& t : types)
  {
    if (type == t.first)
    {
      return t.second;
    }
  }
  return 0;
}

/// Empty when `count` values of `element` bytes from `offset` fit bufferView `view`.
std::string Fits(const json& document, const std::string& owner, long long view, long long offset, long long count,
  long long element)
{
  std::string error = Refers(document, owner, "bufferView", view, "bufferViews");
  if (!error.empty())
  {
    return error;
  }
  const json& v = List(document, "bufferViews")[view];
  const long long stride = std::max(Whole(v, "byteStride", element), element);
  const long long length = Whole(v, "byteLength", 0);
  // Counts are below 2^31 and strides 252 at most: no overflow in 64 bits.
  if (offset < 0 || offset + stride * (count - 1) + element > length)
  {
    return owner + " (" + std::to_string(count) + " values from byte " + std::to_string(offset) +
      ") does not fit its bufferView of " + std::to_string(length) + " bytes";
  }
  return std::string();
}

std::string CheckAccessor(const json& document, size_t i)
{
  const json& a = List(document, "accessors")[i];
  const std::string owner = Named("accessor", i);
  const long long bytes = ComponentBytes(Whole(a, "componentType", -1));
  const long long components = Components(Text(a, "type"));
  const long long count = Whole(a, "count", -1);
  if (bytes == 0 || components == 0 || count < 1 || count > 2147483647LL)
  {
    return owner + " has no valid componentType, type or count";
  }
  std::string error;
  if (a.contains("bufferView"))
  {
    error = Fits(document, owner, Whole(a, "bufferView", -1), Whole(a, "byteOffset", 0), count, bytes * components);
  }
  if (error.empty() && a.contains("sparse"))
  {
    // VTK writes a sparse accessor's values at indices it reads from the file unchecked.
    error = owner + " is sparse, which this reader does not take (an index in it could write anywhere)";
  }
  return error;
}

/// The loader reads indices as unsigned integers and positions and normals as three
/// floats, whatever their accessors say.
std::string Kinds(const json& document, const std::string& owner, const json& primitive)
{
  const auto kind = [&](long long accessor) {
    const json& a = List(document, "accessors")[accessor];
    return std::make_pair(Text(a, "type"), Whole(a, "componentType", -1));
  };
  if (primitive.contains("indices"))
  {
    const long long indices = Whole(primitive, "indices", -1);
    const auto [type, component] = kind(indices);
    if (type != "SCALAR" || (component != 5121 && component != 5123 && component != 5125))
    {
      return owner + "'s indices are not one unsigned integer each";
    }
    if (!List(document, "accessors")[indices].contains("bufferView"))
    {
      return owner + "'s indices have no bufferView";
    }
  }
  for (const char* name : { "POSITION", "NORMAL" })
  {
    const json& attributes = primitive.at("attributes");
    if (attributes.contains(name) && kind(attributes[name].get<long long>()) != std::make_pair(std::string("VEC3"), 5126LL))
    {
      return owner + "'s " + name + " is not three floats per vertex";
    }
  }
  return std::string();
}

std::string CheckMeshes(const json& document)
{
  const json& meshes = List(document, "meshes");
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    for (const json& primitive : List(meshes[m], "primitives"))
    {
      const std::string owner = "a primitive of " + Named("mesh", m);
      for (const auto& attribute : primitive.at("attributes").items())
      {
        const long long accessor = attribute.value().is_number_integer() ? attribute.value().get<long long>() : -1;
        std::string error = Refers(document, owner, attribute.key().c_str(), accessor, "accessors");
        if (!error.empty())
        {
          return error;
        }
      }
      std::string error = primitive.contains("indices")
        ? Refers(document, owner, "indices", Whole(primitive, "indices", -1), "accessors")
        : std::string();
      error = error.empty() ? Kinds(document, owner, primitive) : error;
      for (const json& target : List(primitive, "targets"))
      {
        if (!target.is_object())
        {
          return owner + "'s morph target is not an object";
        }
        for (const auto& attribute : target.items())
        {
          const long long accessor = attribute.value().is_number_integer() ? attribute.value().get<long long>() : -1;
          error = error.empty() ? Refers(document, owner + "'s morph target", attribute.key().c_str(), accessor, "accessors")
                                : error;
        }
      }
      error = error.empty() && primitive.contains("material")
        ? Refers(document, owner, "material", Whole(primitive, "material", -1), "materials")
        : error;
      if (!error.empty())
      {
        return error;
      }
    }
  }
  return std::string();
}

/// Node references, and no node below itself (a cycle makes the loader recurse for ever).
std::string CheckNodes(const json& document)
{
  const json& nodes = List(document, "nodes");
  for (size_t n = 0; n < nodes.size(); ++n)
  {
    const std::string owner = Named("node", n);
    std::string error =
      nodes[n].contains("mesh") ? Refers(document, owner, "mesh", Whole(nodes[n], "mesh", -1), "meshes") : std::string();
    for (const json& child : List(nodes[n], "children"))
    {
      const long long c = child.is_number_integer() ? child.get<long long>() : -1;
      error = error.empty() ? Refers(document, owner, "children", c, "nodes") : error;
    }
    if (!error.empty())
    {
      return error;
    }
  }
  // glTF's node graph is a forest: one parent at most, no cycles. Walked from the roots
  // without recursion, as deep as VTK's own recursion over it can go.
  std::vector<long long> parents(nodes.size(), 0);
  for (const json& node : nodes)
  {
    for (const json& child : List(node, "children"))
    {
      if (++parents[child.get<long long>()] > 1)
      {
        return Named("node", child.get<size_t>()) + " has more than one parent";
      }
    }
  }
  std::vector<std::pair<long long, int>> stack; // node, depth
  for (size_t n = 0; n < nodes.size(); ++n)
  {
    if (parents[n] == 0)
    {
      stack.emplace_back(static_cast<long long>(n), 0);
    }
  }
  size_t reached = 0;
  while (!stack.empty())
  {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    ++reached;
    if (depth > kDeepestNode)
    {
      return "the nodes nest deeper than " + std::to_string(kDeepestNode) + " levels";
    }
    for (const json& child : List(nodes[n], "children"))
    {
      stack.emplace_back(child.get<long long>(), depth + 1);
    }
  }
  return reached == nodes.size() ? std::string() : "the node graph has a cycle (a node is its own ancestor)";
}

/// Animations and skins name accessors and nodes that VTK's loader looks up unchecked.
std::string CheckAnimationsAndSkins(const json& document)
{
  const json& animations = List(document, "animations");
  std::string error;
  for (size_t a = 0; a < animations.size() && error.empty(); ++a)
  {
    const std::string owner = Named("animation", a);
    const json& samplers = List(animations[a], "samplers");
    for (const json& sampler : samplers)
    {
      for (const char* field : { "input", "output" })
      {
        error = error.empty() ? Refers(document, owner + "'s sampler", field, Whole(sampler, field, -1), "accessors") : error;
      }
    }
    for (const json& channel : List(animations[a], "channels"))
    {
      const long long sampler = Whole(channel, "sampler", -1);
      if (error.empty() && (sampler < 0 || sampler >= static_cast<long long>(samplers.size())))
      {
        error = owner + " has a channel naming sampler " + std::to_string(sampler) + " of " + std::to_string(samplers.size());
      }
      const json& target = channel.is_object() && channel.contains("target") ? channel["target"] : json::object();
      error = error.empty() && target.contains("node")
        ? Refers(document, owner + "'s channel", "node", Whole(target, "node", -1), "nodes")
        : error;
    }
  }
  const json& skins = List(document, "skins");
  for (size_t k = 0; k < skins.size() && error.empty(); ++k)
  {
    error = skins[k].contains("inverseBindMatrices")
      ? Refers(document, Named("skin", k), "inverseBindMatrices", Whole(skins[k], "inverseBindMatrices", -1), "accessors")
      : error;
    for (const json& joint : List(skins[k], "joints"))
    {
      error = error.empty() ? Refers(document, Named("skin", k), "joints", joint.is_number_integer() ? joint.get<long long>() : -1, "nodes")
                            : error;
    }
  }
  return error;
}

std::string CheckScenes(const json& document)
{
  const json& scenes = List(document, "scenes");
  for (size_t s = 0; s < scenes.size(); ++s)
  {
    for (const json& node : List(scenes[s], "nodes"))
    {
      std::string error = Refers(document, Named("scene", s), "nodes", node.is_number_integer() ? node.get<long long>() : -1, "nodes");
      if (!error.empty())
      {
        return error;
      }
    }
  }
  return document.contains("scene") ? Refers(document, "the document", "scene", Whole(document, "scene", -1), "scenes")
                                    : std::string();
}

std::string CheckImages(const json& document, const std::string& folder)
{
  const json& images = List(document, "images");
  for (size_t i = 0; i < images.size(); ++i)
  {
    long long size = 0;
    std::string error;
    if (images[i].is_object() && images[i].contains("uri"))
    {
      error = images[i]["uri"].is_string() ? LocalFile(images[i]["uri"].get<std::string>(), folder, size) : "has a uri that is not text";
    }
    else
    {
      error = Refers(document, Named("image", i), "bufferView", Whole(images[i], "bufferView", -1), "bufferViews");
    }
    if (!error.empty())
    {
      return Named("image", i) + ": " + error;
    }
  }
  const json& textures = List(document, "textures");
  for (size_t t = 0; t < textures.size(); ++t)
  {
    std::string error = textures[t].contains("source")
      ? Refers(document, Named("texture", t), "source", Whole(textures[t], "source", -1), "images")
      : std::string();
    if (!error.empty())
    {
      return error;
    }
  }
  return std::string();
}

} // namespace

std::string CheckGltfReferences(const nlohmann::json& document, const std::string& path, long long glbBinary)
{
  const std::string folder = vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path));
  std::string error = CheckBuffers(document, folder, glbBinary);
  error = error.empty() ? CheckViews(document) : error;
  for (size_t i = 0; error.empty() && i < List(document, "accessors").size(); ++i)
  {
    error = CheckAccessor(document, i);
  }
  error = error.empty() ? CheckMeshes(document) : error;
  error = error.empty() ? CheckNodes(document) : error;
  error = error.empty() ? CheckScenes(document) : error;
  error = error.empty() ? CheckAnimationsAndSkins(document) : error;
  return error.empty() ? CheckImages(document, folder) : error;
}

}
