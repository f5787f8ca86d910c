// A walk over a VRML97 file's words before VTK's importer sees it. That importer goes on
// past a syntax error and crashed (a list without its '[', a USE of nothing, a Material or
// an IndexedFaceSet at the top of a file, a list of 3-vectors one number short), so such a
// file gets one error naming its line instead. Words are split by hand: std::regex recurses
// once per character and overflowed the stack on a long name or a long run of spaces.
#include "SceneFiles.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace SceneFiles
{
namespace
{

/// A word of the file, or one of { } [ ], and its line; quoted strings are left out.
struct Word
{
  std::string Text;
  int Line;
};

constexpr size_t kLongestWord = 1000;

/// VTK's VRML parser (a yacc parser of fixed stack) overflows its stack at 1,100 to 1,150
/// nested Transform nodes, 2,200 open braces and brackets, and then reads nothing after
/// walking the whole file (100,000 levels: 117 s). Deeper than this is refused first.
constexpr size_t kDeepest = 2100;

std::vector<Word> Words(const std::string& text)
{
  std::vector<Word> words;
  int line = 1;
  for (size_t k = 0; k < text.size();)
  {
    const char c = text[k];
    if (c == '"')
    {
      for (++k; k < text.size() && text[k] != '"'; ++k)
      {
        line += text[k] == '\n' ? 1 : 0;
        k += text[k] == '\\' ? 1 : 0; // an escaped character, a quote or a backslash
      }
      ++k;
    }
    else if (std::isspace(static_cast<unsigned char>(c)) || c == ',')
    {
      line += c == '\n' ? 1 : 0;
      ++k;
    }
    else if (c == '{' || c == '}' || c == '[' || c == ']')
    {
      words.push_back({ std::string(1, c), line });
      ++k;
    }
    else
    {
      const size_t start = k;
      while (k < text.size() && !std::isspace(static_cast<unsigned char>(text[k])) &&
        std::string(",{}[]\"").find(text[k]) == std::string::npos)
      {
        ++k;
      }
      words.push_back({ text.substr(start, k - start), line });
    }
  }
  return words;
}

std::string At(const Word& word, const std::string& what)
{
  return "line " + std::to_string(word.Line) + ": " + what;
}

std::string Pairing(const std::vector<Word>& words)
{
  std::vector<const Word*> open;
  for (const Word& w : words)
  {
    if (w.Text.size() > kLongestWord)
    {
      return At(w, "a word of " + std::to_string(w.Text.size()) + " characters");
    }
    if (w.Text == "{" || w.Text == "[")
    {
      open.push_back(&w);
      if (open.size() > kDeepest)
      {
        return At(w, "nodes and lists nested more than " + std::to_string(kDeepest) +
            " deep (VTK's VRML parser overflows its stack at about 2,200)");
      }
    }
    else if (w.Text == "}" || w.Text == "]")
    {
      if (open.empty() || open.back()->Text != (w.Text == "}" ? "{" : "["))
      {
        return At(w, "a '" + w.Text + "' that closes nothing open");
      }
      open.pop_back();
    }
  }
  return open.empty() ? std::string() : At(*open.back(), "a '" + open.back()->Text + "' never closed");
}

std::string Names(const std::vector<Word>& words)
{
  std::set<std::string> defined;
  for (size_t i = 0; i + 1 < words.size(); ++i)
  {
    if (words[i].Text == "DEF")
    {
      defined.insert(words[i + 1].Text);
    }
    else if (words[i].Text == "USE" && !defined.count(words[i + 1].Text))
    {
      return At(words[i], "USE " + words[i + 1].Text + " with no DEF " + words[i + 1].Text + " before it");
    }
  }
  return std::string();
}

/// A Material, Appearance, texture or geometry node whose enclosing nodes are all grouping
/// nodes (or none): VTK's importer puts it into the shape it is reading, and outside one
/// it dereferenced nothing. Inside any other node (a PROTO's body, a Sound) it is let be.
std::string Placement(const std::vector<Word>& words)
{
  static const std::set<std::string> inShape = { "Material", "Appearance", "ImageTexture", "PixelTexture",
    "MovieTexture", "TextureTransform", "IndexedFaceSet", "IndexedLineSet", "PointSet", "ElevationGrid",
    "Extrusion", "Box", "Cone", "Cylinder", "Sphere", "Text" };
  static const std::set<std::string> grouping = { "Transform", "Group", "Anchor", "Billboard", "Collision",
    "LOD", "Switch" };
  std::vector<std::string> nodes; // per open brace: the node it opens ("" for other braces)
  for (size_t i = 0; i < words.size(); ++i)
  {
    if (words[i].Text == "}" && !nodes.empty())
    {
      nodes.pop_back();
    }
    if (words[i].Text != "{")
    {
      continue;
    }
    const std::string type = i > 0 ? words[i - 1].Text : std::string();
    const bool loose = std::all_of(nodes.begin(), nodes.end(), [](const std::string& n) { return grouping.count(n) > 0; });
    if (inShape.count(type) && loose)
    {
      const bool vowel = std::string("AEIOU").find(type[0]) != std::string::npos;
      return At(words[i - 1], std::string(vowel ? "an " : "a ") + type +
          " outside any Shape (VRML97 puts it in a Shape's appearance or geometry)");
    }
    nodes.push_back(type);
  }
  return std::string();
}

/// A Coordinate's, Normal's, Color's or TextureCoordinate's list that is not whole vectors
/// of finite numbers.
std::string Lists(const std::vector<Word>& words)
{
  for (size_t i = 0; i + 1 < words.size(); ++i)
  {
    const std::string& type = words[i].Text;
    if (words[i + 1].Text != "{" ||
      (type != "Coordinate" && type != "TextureCoordinate" && type != "Normal" && type != "Color"))
    {
      continue;
    }
    const int size = type == "TextureCoordinate" ? 2 : 3;
    int depth = 0;
    for (size_t j = i + 1; j < words.size(); ++j)
    {
      depth += words[j].Text == "{" ? 1 : words[j].Text == "}" ? -1 : 0;
      if (depth == 0)
      {
        break;
      }
      if (words[j].Text != "[")
      {
        continue;
      }
      int count = 0;
      bool numbers = true;
      for (++j; j < words.size() && words[j].Text != "]"; ++j, ++count)
      {
        char* end = nullptr;
        const double value = std::strtod(words[j].Text.c_str(), &end);
        numbers = numbers && *end == '\0' && std::isfinite(value);
      }
      if (!numbers || count % size != 0)
      {
        return At(words[i], "a list of the " + type + " " +
            (numbers ? "has " + std::to_string(count) + " numbers, not a whole number of " + std::to_string(size) +
                  "-vectors"
                     : "holds something that is not a finite number"));
      }
    }
  }
  return std::string();
}
} // namespace

std::string CheckVrmlText(const std::string& text)
{
  const std::vector<Word> words = Words(text);
  for (std::string (*check)(const std::vector<Word>&) : { Pairing, Names, Placement, Lists })
  {
    const std::string problem = check(words);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

} // namespace SceneFiles
