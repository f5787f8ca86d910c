// A walk over a PLY file before vtkPLYReader sees it. That reader trusts the header: a
// count larger than the file, a list longer than its line or an index past the vertices
// ends in an assert or a crash inside VTK. Here every count, list and face index is held
// against what the file holds, so such a file gets one error instead.
#include "SceneFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

namespace SceneFiles
{
namespace
{

enum class Encoding
{
  Ascii,
  Little,
  Big
};

struct Property
{
  std::string Name;
  int Size = 0;      ///< bytes of the value, or of a list's items
  int CountSize = 0; ///< bytes of a list's count; 0 for a single value
  bool Integer = false;
  bool Signed = false;
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;
};

struct Header
{
  Encoding Format = Encoding::Ascii;
  std::vector<Element> Elements;
  size_t DataStart = 0;
};

/// Size in bytes of a PLY scalar type; 0 for a name PLY does not have.
int TypeSize(const std::string& type, bool& integer, bool& isSigned)
{
  static const struct
  {
    const char* Names[2];
    int Size;
    bool Integer, Signed;
  } types[] = { { { "char", "int8" }, 1, true, true }, { { "uchar", "uint8" }, 1, true, false },
    { { "short", "int16" }, 2, true, true }, { { "ushort", "uint16" }, 2, true, false },
    { { "int", "int32" }, 4, true, true }, { { "uint", "uint32" }, 4, true, false },
    { { "float", "float32" }, 4, false, true }, { { "double", "float64" }, 8, false, true } };
  for (const auto& t : types)
  {
    if (type == t.Names[0] || type == t.Names[1])
    {
      integer = t.Integer;
      isSigned = t.Signed;
      return t.Size;
    }
  }
  return 0;
}

std::string ParseProperty(std::istringstream& words, Element& element)
{
  Property p;
  std::string type;
  words >> type;
  bool integer = false, isSigned = false;
  if (type == "list")
  {
    std::string countType;
    words >> countType >> type;
    p.CountSize = TypeSize(countType, integer, isSigned);
    if (p.CountSize == 0 || !integer)
    {
      return "a list's count type '" + countType + "' is not an integer type";
    }
  }
  p.Size = TypeSize(type, p.Integer, p.Signed);
  words >> p.Name;
  if (p.Size == 0 || p.Name.empty())
  {
    return "the property type '" + type + "' is not a PLY type";
  }
  element.Properties.push_back(p);
  return std::string();
}

std::string ParseElement(std::istringstream& words, Header& header)
{
  Element e;
  std::string count;
  words >> e.Name >> count;
  char* end = nullptr;
  const long long n = std::strtoll(count.c_str(), &end, 10);
  if (count.empty() || *end != '\0' || n < 0 || n > 2147483647LL)
  {
    return "element '" + e.Name + "' has the count '" + count + "' (a whole number from 0 to 2^31 - 1 is a count)";
  }
  e.Count = n;
  header.Elements.push_back(e);
  return std::string();
}

/// vtkPLYReader reads a line into 4,096 characters and splits it at spaces and tabs only.
constexpr size_t kLongestHeaderLine = 4094;

std::string ParseHeader(const std::string& data, Header& header)
{
  if (data.compare(0, 4, "ply\n") != 0 && data.compare(0, 5, "ply\r\n") != 0)
  {
    return "it does not start with 'ply'";
  }
  size_t at = data.find('\n') + 1;
  bool format = false;
  while (at < data.size())
  {
    const size_t next = data.find('\n', at);
    if (next == std::string::npos)
    {
      break;
    }
    const std::string line = data.substr(at, next - at);
    if (line.size() >= kLongestHeaderLine ||
      std::any_of(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 32 && c != '\t' && c != '\r'; }))
    {
      return "a header line is longer than " + std::to_string(kLongestHeaderLine) + " characters or holds a control character";
    }
    std::istringstream words(line);
    at = next + 1;
    std::string keyword;
    words >> keyword;
    std::string error;
    if (keyword == "end_header")
    {
      header.DataStart = at;
      return format ? std::string() : "it has no 'format' line";
    }
    if (keyword == "format")
    {
      std::string name;
      words >> name;
      format = true;
      header.Format = name == "ascii" ? Encoding::Ascii : name == "binary_big_endian" ? Encoding::Big : Encoding::Little;
      if (name != "ascii" && name != "binary_little_endian" && name != "binary_big_endian")
      {
        return "its format is '" + name + "', not ascii or binary";
      }
    }
    else if (keyword == "element")
    {
      error = ParseElement(words, header);
    }
    else if (keyword == "property")
    {
      error = header.Elements.empty() ? "it has a property before any element" : ParseProperty(words, header.Elements.back());
    }
    if (!error.empty())
    {
      return error;
    }
  }
  return "it has no 'end_header' line";
}

/// Reads the values of a file's data part in its encoding, one at a time.
class Values
{
public:
  Values(const std::string& data, const Header& header)
    : Data(data)
    , Format(header.Format)
    , At(header.DataStart)
  {
  }

  /// Moves to the next element's values: in ASCII, its line (vtkPLYReader reads one line
  /// per element and asserts when a line has too few words). False at the end of the data.
  bool Start()
  {
    if (Format != Encoding::Ascii)
    {
      return true; // a short binary file is found by the value that is missing
    }
    const size_t next = At < Data.size() ? Data.find('\n', At) : std::string::npos;
    if (next == std::string::npos || next - At >= kLongestLine)
    {
      return false; // vtkPLYReader asserts on a last line without its end, and splits long ones
    }
    // It reads a line as a C string (a NUL byte ends it) and stops at a carriage return.
    // Looked for in the line only: over the rest of the file, per line, a 16k-face file
    // took 23 s.
    const auto line = Data.begin() + static_cast<std::ptrdiff_t>(At);
    LineEnd = At + static_cast<size_t>(std::find_if(line, Data.begin() + static_cast<std::ptrdiff_t>(next),
                                                    [](char c) { return c == '\r' || c == '\0'; }) - line);
    After = next + 1;
    return true;
  }

  /// Moves past the element's values.
  void Finish()
  {
    if (Format == Encoding::Ascii)
    {
      At = After;
    }
  }

  /// The next value of `size` bytes as a number; false at the end of the data (in ASCII,
  /// of the line).
  bool Next(int size, bool integer, bool isSigned, double& value)
  {
    return Format == Encoding::Ascii ? NextWord(value) : NextBinary(size, integer, isSigned, value);
  }

private:
  /// A word as vtkPLYReader splits a line: at spaces and tabs only ("0-0" and "0\f0" are
  /// one word each).
  static bool Gap(char c) { return c == ' ' || c == '\t'; }
  bool NextWord(double& value)
  {
    while (At < LineEnd && Gap(Data[At]))
    {
      ++At;
    }
    if (At >= LineEnd)
    {
      return false;
    }
    const size_t start = At;
    while (At < LineEnd && !Gap(Data[At]))
    {
      ++At;
    }
    const std::string word = Data.substr(start, At - start);
    char* end = nullptr;
    value = std::strtod(word.c_str(), &end);
    // vtkPLYReader rewrites some words inside a line ("vertex_index") and cuts the line there.
    Garbled = end != word.c_str() + word.size();
    return !Garbled;
  }

  bool NextBinary(int size, bool integer, bool isSigned, double& value)
  {
    if (Data.size() - At < static_cast<size_t>(size))
    {
      return false;
    }
    unsigned char bytes[8];
    for (int i = 0; i < size; ++i)
    {
      bytes[i] = static_cast<unsigned char>(Data[At + (Format == Encoding::Big ? size - 1 - i : i)]);
    }
    At += size;
    std::uint64_t bits = 0;
    for (int i = size - 1; i >= 0; --i)
    {
      bits = (bits << 8) | bytes[i];
    }
    if (!integer)
    {
      value = size == 4 ? Float(static_cast<std::uint32_t>(bits)) : Double(bits);
      return true;
    }
    const std::uint64_t sign = std::uint64_t(1) << (8 * size - 1);
    value = isSigned && (bits & sign) ? static_cast<double>(bits) - 2.0 * static_cast<double>(sign) : static_cast<double>(bits);
    return true;
  }

  static double Float(std::uint32_t bits)
  {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  static double Double(std::uint64_t bits)
  {
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }

  const std::string& Data;
  Encoding Format;
  size_t At;
  size_t LineEnd = 0, After = 0;
  bool Garbled = false;

public:
  /// The last word read was not a number.
  bool NotANumber() const { return Garbled; }
  /// vtkPLYReader reads a line into 4,096 characters; a longer one continues as the next.
  static constexpr size_t kLongestLine = 4094;
};

std::string Ordinal(long long i, long long count, const std::string& name)
{
  return name + " " + std::to_string(i + 1) + " of " + std::to_string(count);
}

/// One element's values: lists no longer than what is left, face indices below `vertices`.
std::string WalkElement(const Element& e, long long vertices, Values& values)
{
  const bool faces = e.Name == "face";
  const std::string ends = "the file ends inside ";
  for (long long i = 0; i < e.Count; ++i)
  {
    if (!values.Start())
    {
      return ends + Ordinal(i, e.Count, e.Name) + ": the header promises more than it holds";
    }
    for (const Property& p : e.Properties)
    {
      double count = 1;
      if (p.CountSize > 0 && !values.Next(p.CountSize, true, false, count))
      {
        return values.NotANumber() ? Ordinal(i, e.Count, e.Name) + " holds a word that is not a number"
                                   : ends + Ordinal(i, e.Count, e.Name) + ": the header promises more than it holds";
      }
      if (count < 0 || count > 1e6)
      {
        return Ordinal(i, e.Count, e.Name) + " has a list of " + std::to_string(static_cast<long long>(count)) + " items";
      }
      const bool indices = faces && p.CountSize > 0 && (p.Name == "vertex_indices" || p.Name == "vertex_index");
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        double v = 0;
        if (!values.Next(p.Size, p.Integer, p.Signed, v))
        {
          return values.NotANumber() ? Ordinal(i, e.Count, e.Name) + " holds a word that is not a number"
                                     : ends + Ordinal(i, e.Count, e.Name) + ": the header promises more than it holds";
        }
        v = indices ? std::trunc(v) : v; // the reader keeps an index as an int
        if (indices && !(v >= 0 && v < static_cast<double>(vertices)))
        {
          return Ordinal(i, e.Count, e.Name) + " names vertex " + std::to_string(static_cast<long long>(v)) +
            ", and the file has " + std::to_string(vertices);
        }
      }
    }
    values.Finish();
  }
  return std::string();
}

} // namespace

/// What vtkPLYReader assumes of the elements: the vertices first, with x, y and z, then
/// the faces (if any) with a list of vertex indices; it does not skip other elements' data.
std::string CheckLayout(const Header& header)
{
  const auto named = [](const Element& e, const std::string& name) {
    return std::find_if(e.Properties.begin(), e.Properties.end(), [&](const Property& p) { return p.Name == name; });
  };
  if (header.Elements.empty() || header.Elements[0].Name != "vertex")
  {
    return "its first element is not 'vertex'";
  }
  const Element& vertex = header.Elements[0];
  const auto faceList = named(vertex, "vertex_indices");
  if (faceList != vertex.Properties.end() && faceList->CountSize > 0)
  {
    // Blender's exporter wrote such a file (assimp's issue623.ply): read on, it looked
    // like a file shorter than its header, which it is not.
    return "its vertices have the list 'vertex_indices' that faces hold: the header lacks an 'element face' line";
  }
  for (const char* axis : { "x", "y", "z" })
  {
    const auto p = named(vertex, axis);
    if (p == vertex.Properties.end() || p->CountSize > 0)
    {
      return std::string("its vertices have no single value '") + axis + "'";
    }
  }
  for (size_t i = 1; i < header.Elements.size(); ++i)
  {
    const std::string& name = header.Elements[i].Name;
    if ((name == "face" && i != 1) || name == "vertex")
    {
      return "element '" + name + "' comes where vtkPLYReader does not look for it (vertex first, then face)";
    }
  }
  if (header.Elements.size() > 1 && header.Elements[1].Name == "face")
  {
    const Element& face = header.Elements[1];
    const auto list = std::find_if(face.Properties.begin(), face.Properties.end(),
      [](const Property& p) { return p.CountSize > 0 && (p.Name == "vertex_indices" || p.Name == "vertex_index"); });
    if (list == face.Properties.end())
    {
      return "its faces have no list 'vertex_indices'";
    }
  }
  return std::string();
}

namespace
{
bool RealColors(const Header& header)
{
  for (const Element& e : header.Elements)
  {
    for (const Property& p : e.Properties)
    {
      if ((p.Name == "red" || p.Name == "green" || p.Name == "blue") && !p.Integer)
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

std::string CheckPly(const std::string& path, bool* realColors)
{
  std::string data;
  ReadText(path, data);
  Header header;
  std::string error = ParseHeader(data, header);
  if (realColors)
  {
    *realColors = error.empty() && RealColors(header);
  }
  error = error.empty() ? CheckLayout(header) : error;
  long long vertices = 0;
  for (const Element& e : header.Elements)
  {
    vertices = e.Name == "vertex" ? e.Count : vertices;
  }
  Values values(data, header);
  for (size_t i = 0; i < header.Elements.size() && error.empty(); ++i)
  {
    error = WalkElement(header.Elements[i], vertices, values);
  }
  return error.empty() ? error : "'" + path + "' cannot be read as PLY: " + error;
}

}
