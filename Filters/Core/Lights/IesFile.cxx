// IES LM-63: 1986 (no version line), 1991 ("IESNA91"), 1995 ("IESNA:LM-63-1995"), 2002
// ("IESNA:LM-63-2002") and 2019 ("IES:LM-63-2019"): keyword lines, the TILT line, then
// numbers separated by spaces or commas and wrapped across lines at will.
#include "Lights/PhotometricFiles.h"

#include "Lights/NumberTokens.h"
#include "Base/Text.h"

#include <algorithm>
#include <memory>
#include <cctype>
#include <sstream>

namespace radiosity
{

namespace
{
constexpr double kFoot = 0.3048;
constexpr double kMostAngles = 100000; // a goniometer's table is a few thousand at most

std::string Upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// The year of the format, from the first line (1986 where there is no version line).
int FormatYear(const std::string& first)
{
  const std::string line = Upper(Trimmed(first));
  if (line.rfind("IESNA91", 0) == 0)
  {
    return 1991;
  }
  for (const char* year : { "1995", "2002", "2019" })
  {
    if ((line.rfind("IESNA", 0) == 0 || line.rfind("IES:", 0) == 0) && line.find(year) != std::string::npos)
    {
      return std::stoi(year);
    }
  }
  return line.rfind("IESNA", 0) == 0 || line.rfind("IES:", 0) == 0 ? 2002 : 1986;
}

/// The folder part of a path, with its slash ("" for none).
std::string Folder(const std::string& path)
{
  const size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

/// A count: a whole number in [1, most].
bool Count(NumberTokens& in, const char* what, double most, size_t& count)
{
  double v;
  if (!in.Next(what, v))
  {
    return false;
  }
  if (v != std::floor(v) || v < 1 || v > most)
  {
    std::ostringstream s;
    s << what << " is " << v << ", not a whole number from 1 to " << most;
    return in.Fail(in.Line(), s.str());
  }
  count = static_cast<size_t>(v);
  return true;
}

/// `count` angles, each above the one before.
bool Angles(NumberTokens& in, const char* what, size_t count, std::vector<double>& angles)
{
  angles.resize(count);
  for (size_t i = 0; i < count; ++i)
  {
    if (!in.Next(what, angles[i]))
    {
      return false;
    }
    if (i > 0 && !(angles[i] > angles[i - 1]))
    {
      std::ostringstream s;
      s << what << " out of order: " << angles[i - 1] << " then " << angles[i];
      return in.Fail(in.Line(), s.str());
    }
  }
  return true;
}

/// The tilt block (after TILT=INCLUDE, or a TILT file's numbers).
bool ReadTilt(NumberTokens& in, PhotometricWeb& out)
{
  double geometry;
  size_t count;
  if (!in.Next("the lamp-to-luminaire geometry", geometry) || !Count(in, "the number of tilt angles", kMostAngles, count))
  {
    return false;
  }
  out.TiltGeometry = static_cast<int>(geometry);
  if (!Angles(in, "tilt angles", count, out.TiltAngles) || !in.Take("a tilt factor", count, out.TiltFactors))
  {
    return false;
  }
  for (double f : out.TiltFactors)
  {
    if (f < 0)
    {
      return in.Fail(in.Line(), "a negative tilt factor");
    }
  }
  return true;
}

/// TILT=<file>: the tilt block from a file beside this one.
std::string ReadTiltFile(const std::string& tilt, const std::string& name, const NumberedLine& line,
  const TextReader& read, PhotometricWeb& out)
{
  const std::string path = tilt.find_first_of("/\\") == 0 ? tilt : Folder(name) + tilt;
  std::string text;
  if (!read || !read(path, text))
  {
    return name + ":" + std::to_string(line.Number) + ": the TILT file " + ValidUtf8(path) + " cannot be read";
  }
  NumberTokens numbers(SplitLines(text), 0, path);
  return ReadTilt(numbers, out) ? std::string() : numbers.Error();
}

/// The candela table, row by row of horizontal angles, into out.Candela in the web's
/// [azimuth][polar] order (type B's rows are its latitudes: transposed).
bool ReadCandela(NumberTokens& in, size_t verticals, size_t horizontals, double scale, PhotometricWeb& out)
{
  out.Candela.assign(verticals * horizontals, 0.0);
  for (size_t h = 0; h < horizontals; ++h)
  {
    for (size_t v = 0; v < verticals; ++v)
    {
      double cd;
      if (!in.Next("a candela value", cd))
      {
        return false;
      }
      if (cd < 0)
      {
        std::ostringstream s;
        s << "negative candela " << cd << " (horizontal angle " << h + 1 << ", vertical angle " << v + 1 << ")";
        return in.Fail(in.Line(), s.str());
      }
      const size_t at = out.Type == PhotometricType::B ? v * horizontals + h : h * verticals + v;
      out.Candela[at] = cd * scale;
    }
  }
  return true;
}
} // namespace

namespace
{
/// The tilt the TILT= line names, read into `out` (nothing for NONE, the numbers after it
/// for INCLUDE, a file beside for a name), and `numbers` the file's numbers after it.
/// Empty, or the problem.
std::string ReadTiltLine(const std::vector<NumberedLine>& lines, const std::string& name, const TextReader& read,
  std::unique_ptr<NumberTokens>& numbers, PhotometricWeb& out)
{
  size_t tilt = 0;
  while (tilt < lines.size() && Upper(Trimmed(lines[tilt].Text)).rfind("TILT", 0) != 0)
  {
    ++tilt;
  }
  if (tilt == lines.size())
  {
    return name + ": no TILT line, so not IES LM-63 (every version has one before its numbers)";
  }
  const std::string tiltLine = Trimmed(lines[tilt].Text);
  const size_t equals = tiltLine.find('=');
  const std::string tiltValue = equals == std::string::npos ? std::string() : Trimmed(tiltLine.substr(equals + 1));
  numbers.reset(new NumberTokens(lines, tilt + 1, name)); // the numbers after the TILT line
  if (Upper(tiltValue) == "INCLUDE")
  {
    return ReadTilt(*numbers, out) ? std::string() : numbers->Error();
  }
  return Upper(tiltValue) == "NONE" ? std::string() : ReadTiltFile(tiltValue, name, lines[tilt], read, out);
}

/// The luminaire line and the ballast line: type, units, opening, lumens; `scale` the
/// factor every candela value takes, `verticals` and `horizontals` the table's size.
bool ReadFields(NumberTokens& in, int year, PhotometricWeb& out, double& scale, size_t& verticals, size_t& horizontals)
{
  double lamps, lumensPerLamp, multiplier, type, units, width, length, height, ballast, lampFactor, watts;
  if (!in.Next("the number of lamps", lamps) || !in.Next("the lumens per lamp", lumensPerLamp) ||
    !in.Next("the candela multiplier", multiplier) || !Count(in, "the number of vertical angles", kMostAngles, verticals) ||
    !Count(in, "the number of horizontal angles", kMostAngles, horizontals) || !in.Next("the photometric type", type))
  {
    return false;
  }
  if (type != 1 && type != 2 && type != 3)
  {
    std::ostringstream s;
    s << "unknown photometric type " << type << " (1 is C, 2 is B, 3 is A)";
    return in.Fail(in.Line(), s.str());
  }
  out.Type = static_cast<PhotometricType>(static_cast<int>(type));
  if (!in.Next("the units type", units) || !in.Next("the width", width) || !in.Next("the length", length) ||
    !in.Next("the height", height) || !in.Next("the ballast factor", ballast) ||
    !in.Next("the ballast-lamp factor", lampFactor) || !in.Next("the input watts", watts))
  {
    return false;
  }
  if (units != 1 && units != 2)
  {
    std::ostringstream s;
    s << "unknown units type " << units << " (1 is feet, 2 is metres)";
    return in.Fail(in.Line(), s.str());
  }
  if (!(multiplier > 0) || !(ballast > 0))
  {
    return in.Fail(in.Line(), "the candela multiplier and the ballast factor must be above 0");
  }
  const double metres = units == 1 ? kFoot : 1.0;
  out.Opening = { width * metres, length * metres, height * metres };
  out.LampLumens = lumensPerLamp > 0 && lamps > 0 ? lumensPerLamp * lamps : 0; // -1: absolute photometry
  // Before LM-63-2002 the second factor was the ballast-lamp photometric factor; since, a
  // field for future use (2019: the file's generation type), never a multiplier.
  scale = multiplier * ballast * (year < 2002 && lampFactor > 0 ? lampFactor : 1.0);
  return true;
}
} // namespace

std::string ParseIes(const std::string& text, const std::string& name, PhotometricWeb& out, const TextReader& read)
{
  out = PhotometricWeb();
  out.Source = name;
  const std::vector<NumberedLine> lines = SplitLines(text);
  if (lines.empty())
  {
    return name + ": an empty file, not IES LM-63";
  }
  std::unique_ptr<NumberTokens> in;
  std::string problem = ReadTiltLine(lines, name, read, in, out);
  if (!problem.empty())
  {
    return problem;
  }
  double scale;
  size_t verticals, horizontals;
  std::vector<double> verticalAngles, horizontalAngles;
  if (!ReadFields(*in, FormatYear(lines[0].Text), out, scale, verticals, horizontals) ||
    !Angles(*in, "vertical angles", verticals, verticalAngles) ||
    !Angles(*in, "horizontal angles", horizontals, horizontalAngles))
  {
    return in->Error();
  }
  const bool typeB = out.Type == PhotometricType::B;
  out.Azimuth = typeB ? verticalAngles : horizontalAngles;
  out.Polar = typeB ? horizontalAngles : verticalAngles;
  const int tableLine = in->Line();
  if (!ReadCandela(*in, verticals, horizontals, scale, out))
  {
    return in->Error();
  }
  problem = PhotometricProblem(out);
  return problem.empty() ? problem : name + ":" + std::to_string(tableLine) + ": " + problem;
}

} // namespace radiosity
