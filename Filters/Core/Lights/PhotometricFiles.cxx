#include "Lights/PhotometricFiles.h"

#include "Lights/NumberTokens.h"
#include "Base/Text.h"

#include <algorithm>
#include <cctype>
#include <clocale>
#include <fstream>
#include <sstream>

namespace radiosity
{

std::vector<NumberedLine> SplitLines(const std::string& text)
{
  std::vector<NumberedLine> lines;
  size_t start = 0;
  int number = 1;
  for (size_t i = 0; i <= text.size(); ++i)
  {
    if (i == text.size() || text[i] == '\n' || text[i] == '\r')
    {
      if (i < text.size() || i > start)
      {
        lines.push_back({ text.substr(start, i - start), number++ });
      }
      if (i + 1 < text.size() && text[i] == '\r' && text[i + 1] == '\n')
      {
        ++i;
      }
      start = i + 1;
    }
  }
  return lines;
}

bool ParseNumber(const std::string& word, double& value)
{
  if (word.empty())
  {
    return false;
  }
  // istringstream in the classic locale: strtod would read "1,5" as 1 under a German locale.
  std::istringstream in(word);
  in.imbue(std::locale::classic());
  in >> value;
  return !in.fail() && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

NumberTokens::NumberTokens(const std::vector<NumberedLine>& lines, size_t first, std::string name)
  : Name(std::move(name))
{
  for (size_t i = first; i < lines.size(); ++i)
  {
    std::string word;
    for (char c : lines[i].Text + " ")
    {
      if (c == ' ' || c == '\t' || c == ',' || c == '\f' || c == '\v')
      {
        if (!word.empty())
        {
          Tokens.push_back({ word, lines[i].Number });
        }
        word.clear();
      }
      else
      {
        word += c;
      }
    }
  }
  LastLine = lines.empty() ? 0 : lines.back().Number;
}

bool NumberTokens::Next(const char* what, double& value)
{
  if (At >= Tokens.size())
  {
    return Fail(LastLine, std::string("the file ends where ") + what + " should follow");
  }
  const Token& t = Tokens[At++];
  LastLine = t.Line;
  if (!ParseNumber(t.Word, value))
  {
    return Fail(t.Line, std::string("'") + ValidUtf8(t.Word.substr(0, 40)) + "' is not a number (" + what + ")");
  }
  return true;
}

bool NumberTokens::Take(const char* what, size_t count, std::vector<double>& values)
{
  values.resize(count);
  for (double& v : values)
  {
    if (!Next(what, v))
    {
      return false;
    }
  }
  return true;
}

bool NumberTokens::Fail(int line, const std::string& what)
{
  Error_ = Name + ":" + std::to_string(line) + ": " + what;
  return false;
}

bool ReadTextFile(const std::string& path, std::string& text)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0 || size > (64 << 20))
  {
    return false;
  }
  in.seekg(0);
  text.assign(static_cast<size_t>(size), '\0');
  in.read(&text[0], size);
  return static_cast<bool>(in) || size == 0;
}

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool EndsWith(const std::string& s, const std::string& tail)
{
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
} // namespace

std::string ReadPhotometricFile(const std::string& path, PhotometricWeb& out)
{
  std::string text;
  if (!ReadTextFile(path, text))
  {
    return path + ": cannot be read (missing, unreadable or over 64 MiB)";
  }
  const std::string lower = Lower(path);
  const bool ies = EndsWith(lower, ".ies") ||
    (!EndsWith(lower, ".ldt") && (Lower(text.substr(0, 5)) == "iesna" || Lower(text.substr(0, 4)) == "ies:" ||
                                   Lower(text).find("tilt=") != std::string::npos));
  return ies ? ParseIes(text, path, out, ReadTextFile) : ParseEulumdat(text, path, out);
}

} // namespace radiosity
