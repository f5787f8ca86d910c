// The numbers of a photometric file, each with the line it stands on, for messages that
// say where a file went wrong.
#ifndef RadiosityCore_NumberTokens_h
#define RadiosityCore_NumberTokens_h

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace radiosity
{

/// One line of a file, numbered from 1.
struct NumberedLine
{
  std::string Text;
  int Number = 0;
};

/// The file's lines, with "\r\n", "\r" and "\n" all ending one.
std::vector<NumberedLine> SplitLines(const std::string& text);

/// Whole text as a finite number (a C locale double), or false.
bool ParseNumber(const std::string& word, double& value);

/// Numbers separated by spaces, tabs or commas, across lines, read in order.
class NumberTokens
{
public:
  NumberTokens(const std::vector<NumberedLine>& lines, size_t first, std::string name);
  /// The next number into `value`, or false with Error() saying what and where.
  bool Next(const char* what, double& value);
  /// `count` numbers, or false.
  bool Take(const char* what, size_t count, std::vector<double>& values);
  /// The line of the last number read (of the file's end where none is left).
  int Line() const { return LastLine; }
  const std::string& Error() const { return Error_; }
  /// Sets Error() to "<name>:<line>: <what>" and returns false.
  bool Fail(int line, const std::string& what);

private:
  struct Token
  {
    std::string Word;
    int Line;
  };
  std::vector<Token> Tokens;
  size_t At = 0;
  int LastLine = 0;
  std::string Name, Error_;
};

} // namespace radiosity

#endif
