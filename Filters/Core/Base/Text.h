// Small text helpers shared by the file parsers.
#ifndef RadiosityCore_Text_h
#define RadiosityCore_Text_h

#include <cctype>
#include <string>

namespace radiosity
{

/// `text` without leading and trailing spaces, tabs and line ends.
inline std::string Trimmed(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t\r\n");
  const size_t last = text.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

/// `text` with every byte that is not part of a well-formed UTF-8 sequence read as Latin-1
/// (the likeliest older encoding; two such names stay two), '?' for its control bytes
/// 0x80-0x9f: names and messages taken from a file reach Python and Qt, which refuse (or
/// drop) the whole string otherwise.
inline std::string ValidUtf8(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();)
  {
    const unsigned char lead = static_cast<unsigned char>(text[i]);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
    bool whole = length > 0 && i + length <= text.size() && !(length == 2 && lead < 0xC2);
    for (int k = 1; whole && k < length; ++k)
    {
      whole = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    }
    if (whole && length >= 3)
    {
      // Overlong forms, UTF-16 surrogates and values past U+10FFFF are not UTF-8 either.
      const unsigned char second = static_cast<unsigned char>(text[i + 1]);
      whole = !(lead == 0xE0 && second < 0xA0) && !(lead == 0xED && second >= 0xA0) &&
        !(lead == 0xF0 && second < 0x90) && !(lead == 0xF4 && second >= 0x90) && lead <= 0xF4;
    }
    if (whole)
    {
      out.append(text, i, static_cast<size_t>(length));
    }
    else if (lead < 0xA0)
    {
      out += '?'; // Latin-1's C1 controls: U+0085 alone ends a line in Python and Qt
    }
    else
    {
      out += static_cast<char>(0xC0 | (lead >> 6));
      out += static_cast<char>(0x80 | (lead & 0x3F));
    }
    i += whole ? length : 1;
  }
  return out;
}

/// Shell-style match, ignoring case: `*` any run of characters, `?` any one.
inline bool MatchesPattern(const std::string& pattern, const std::string& text)
{
  // Greedy wildcard matching with one backtrack point: the last '*' seen.
  size_t p = 0, t = 0, star = std::string::npos, resume = 0;
  auto same = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  };
  while (t < text.size())
  {
    if (p < pattern.size() && (pattern[p] == '?' || (pattern[p] != '*' && same(pattern[p], text[t]))))
    {
      ++p;
      ++t;
    }
    else if (p < pattern.size() && pattern[p] == '*')
    {
      star = p++;
      resume = t;
    }
    else if (star != std::string::npos)
    {
      p = star + 1;
      t = ++resume;
    }
    else
    {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*')
  {
    ++p;
  }
  return p == pattern.size();
}

} // namespace radiosity

#endif
