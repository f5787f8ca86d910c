// Small text helpers shared by the file parsers.
#ifndef RadiosityCore_Text_h
#define RadiosityCore_Text_h

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

} // namespace radiosity

#endif
