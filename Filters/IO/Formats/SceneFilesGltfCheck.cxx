// What a glTF file says about its own data, held against that data before VTK's loader
// trusts it: an index past a list, a range past its buffer, a file outside the model's
// folder or a node graph with a cycle crash that loader (or read what is not the model's).
#include "SceneFilesGltfCheck.h"

#include <vtksys/SystemTools.hxx>

#include <sys/stat.h>

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
  return v.is_number_integer() || v.is_number_unsigned() ? v.get<long long>() : -1;
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
  struct stat info;
  const std::string path = folder + "/" + uri;
  if (stat(path.c_str(), &info) != 0)
  {
    return "'" + uri + "' is missing";
  }
  if (!S_ISREG(info.st_mode))
  {
    return "'" + uri + "' is not a regular file";
  }
  size = static_cast<long long>(info.st_size);
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
    if (error.empty() && held < length)
    {
      error = "claims " + std::to_string(length) + " bytes and holds " + std::to_string(held);
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
    if (offset < 0 || length < 0 || offset + length > held || stride < 1 || stride > 252)
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
  const long long components = Components(a.is_object() ? a.value("type", "") : "");
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
    const json& sparse = a["sparse"];
    const long long changed = Whole(sparse, "count", -1);
    const json& indices = sparse.is_object() ? sparse.value("indices", json::object()) : json::object();
    const json& values = sparse.is_object() ? sparse.value("values", json::object()) : json::object();
    error = changed < 1 || changed > count ? owner + "'s sparse count is not from 1 to its count" : std::string();
    error = error.empty() ? Fits(document, owner + "'s sparse indices", Whole(indices, "bufferView", -1),
                              Whole(indices, "byteOffset", 0), changed, ComponentBytes(Whole(indices, "componentType", -1)))
                          : error;
    error = error.empty() ? Fits(document, owner + "'s sparse values", Whole(values, "bufferView", -1),
                              Whole(values, "byteOffset", 0), changed, bytes * components)
                          : error;
  }
  return error;
}

/// The loader reads indices as unsigned integers and positions and normals as three
/// floats, whatever their accessors say.
std::string Kinds(const json& document, const std::string& owner, const json& primitive)
{
  const auto kind = [&](long long accessor) {
    const json& a = List(document, "accessors")[accessor];
    return std::make_pair(a.value("type", std::string()), Whole(a, "componentType", -1));
  };
  if (primitive.contains("indices"))
  {
    const auto [type, component] = kind(Whole(primitive, "indices", -1));
    if (type != "SCALAR" || (component != 5121 && component != 5123 && component != 5125))
    {
      return owner + "'s indices are not one unsigned integer each";
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
  return error.empty() ? CheckImages(document, folder) : error;
}

}
