// EULUMDAT (.ldt): one field a line in a fixed order, the lamp sets, ten direct ratios,
// the C and gamma angles, then the intensities in cd/klm of the planes the symmetry keeps.
#include "Lights/PhotometricFiles.h"

#include "Lights/NumberTokens.h"
#include "Base/Text.h"

#include <cmath>
#include <sstream>

namespace radiosity
{

namespace
{
constexpr int kHeaderLines = 26; // through the number of lamp sets
constexpr double kMillimetre = 1e-3;

/// Reads the fixed lines one at a time, each a single field.
class LdtLines
{
public:
  LdtLines(const std::vector<NumberedLine>& lines, std::string name)
    : Lines(lines)
    , Name(std::move(name))
  {
  }
  bool Number(const char* what, double& value)
  {
    if (At >= Lines.size())
    {
      return Fail("the file ends where " + std::string(what) + " should be");
    }
    const std::string word = Trimmed(Lines[At++].Text);
    if (!ParseNumber(word, value))
    {
      return Fail("'" + ValidUtf8(word.substr(0, 40)) + "' is not a number (" + what + ")");
    }
    return true;
  }
  bool Whole(const char* what, double lo, double hi, int& value)
  {
    double v;
    if (!Number(what, v))
    {
      return false;
    }
    if (v != std::floor(v) || v < lo || v > hi)
    {
      std::ostringstream s;
      s << what << " is " << v << ", not a whole number from " << lo << " to " << hi;
      return Fail(s.str());
    }
    value = static_cast<int>(v);
    return true;
  }
  bool Skip(size_t count)
  {
    if (At + count > Lines.size())
    {
      At = Lines.size();
      return Fail("the file ends inside its header");
    }
    At += count;
    return true;
  }
  /// True where the next line holds a number (the lamp sets' layout tells by it).
  bool NextIsNumber() const
  {
    double v;
    return At < Lines.size() && ParseNumber(Trimmed(Lines[At].Text), v);
  }
  bool Fail(const std::string& what)
  {
    const int line = Lines.empty() ? 0 : Lines[std::min(At, Lines.size()) - (At > 0 ? 1 : 0)].Number;
    Error = Name + ":" + std::to_string(line) + ": " + what;
    return false;
  }
  size_t Position() const { return At; }
  /// values.size() numbers, one a line; false at the first that is not one.
  bool Numbers(const char* what, std::vector<double>& values)
  {
    for (double& v : values)
    {
      if (!Number(what, v))
      {
        return false;
      }
    }
    return true;
  }
  /// The line number of the i-th of the last `count` numbers read.
  int LineOf(size_t i, size_t count) const { return Lines[At - count + i].Number; }
  std::string Error;

private:
  const std::vector<NumberedLine>& Lines;
  std::string Name;
  size_t At = 0;
};

/// Lamp sets: six lines each (count, type, flux, colour, rendering, watts). The format's
/// text lists each field for every set in turn; some writers give set after set instead,
/// which shows as text where the second set's count should be.
bool ReadLampSets(LdtLines& in, int sets, double& flux)
{
  flux = 0;
  double lamps, sum;
  if (!in.Number("the number of lamps", lamps))
  {
    return false;
  }
  const bool fieldBySet = sets == 1 || in.NextIsNumber();
  if (fieldBySet)
  {
    if (!in.Skip(sets - 1 + sets)) // the other counts, then the lamp types
    {
      return false;
    }
    for (int s = 0; s < sets; ++s)
    {
      if (!in.Number("a lamp set's luminous flux", sum))
      {
        return false;
      }
      flux += std::fabs(sum);
    }
    return in.Skip(3 * static_cast<size_t>(sets));
  }
  for (int s = 0; s < sets; ++s)
  {
    if ((s > 0 && !in.Number("the number of lamps", lamps)) || !in.Skip(1) ||
      !in.Number("a lamp set's luminous flux", sum) || !in.Skip(3))
    {
      return false;
    }
    flux += std::fabs(sum);
  }
  return true;
}

/// The first plane and the number of planes the symmetry indicator keeps of mc.
bool StoredPlanes(int symmetry, int mc, int& first, int& count)
{
  const int stored[5] = { mc, 1, mc / 2 + 1, mc / 2 + 1, mc / 4 + 1 };
  first = symmetry == 3 ? mc / 4 : 0; // C90 to C270
  count = stored[symmetry];
  return first + count <= mc || symmetry == 1;
}
} // namespace

std::string ParseEulumdat(const std::string& text, const std::string& name, PhotometricWeb& out)
{
  out = PhotometricWeb();
  out.Source = name;
  const std::vector<NumberedLine> lines = SplitLines(text);
  LdtLines in(lines, name);
  int symmetry, mc, ng, sets;
  double dc, dg, dimensions[9], lorl, dff, factor, tilt;
  if (!in.Skip(2) || !in.Whole("the symmetry indicator", 0, 4, symmetry) ||
    !in.Whole("the number of C planes", 1, 3600, mc) || !in.Number("the C plane spacing", dc) ||
    !in.Whole("the number of gamma angles", 1, 3600, ng) || !in.Number("the gamma spacing", dg) || !in.Skip(5))
  {
    return in.Error;
  }
  for (double& d : dimensions)
  {
    if (!in.Number("a luminaire or luminous area dimension", d))
    {
      return in.Error;
    }
  }
  if (!in.Number("the downward flux fraction", dff) || !in.Number("the light output ratio", lorl) ||
    !in.Number("the intensity conversion factor", factor) || !in.Number("the measurement tilt", tilt) ||
    !in.Whole("the number of lamp sets", 1, 100, sets))
  {
    return in.Error;
  }
  double flux;
  if (!ReadLampSets(in, sets, flux) || !in.Skip(10)) // the lamp sets, then the direct ratios
  {
    return in.Error;
  }
  int first, count;
  if (!StoredPlanes(symmetry, mc, first, count))
  {
    return in.Fail("symmetry 3 needs C planes to 270 degrees, and " + std::to_string(mc) + " planes have not"), in.Error;
  }
  std::vector<double> c(mc), gamma(ng), table(static_cast<size_t>(count) * ng);
  if (!in.Numbers("a C angle", c) || !in.Numbers("a gamma angle", gamma) || !in.Numbers("a luminous intensity", table))
  {
    return in.Error;
  }
  for (double& v : table)
  {
    if (v < 0)
    {
      return name + ":" + std::to_string(in.LineOf(&v - table.data(), table.size())) + ": a negative luminous intensity";
    }
  }
  out.Type = PhotometricType::C;
  out.Azimuth = symmetry == 1 ? std::vector<double>{ 0.0 } : std::vector<double>(c.begin() + first, c.begin() + first + count);
  out.Polar = gamma;
  // cd/klm of the lamps' flux (for absolute photometry, of the luminaire's: the same sum).
  const double scale = flux / 1000 * (factor > 0 ? factor : 1.0);
  out.Candela.resize(table.size());
  for (size_t i = 0; i < table.size(); ++i)
  {
    out.Candela[i] = table[i] * scale;
  }
  out.LampLumens = flux;
  out.LuminaireLumens = flux * lorl / 100;
  out.Opening = { dimensions[4] * kMillimetre, dimensions[3] * kMillimetre, dimensions[5] * kMillimetre };
  if (dimensions[4] == 0 && dimensions[3] > 0)
  {
    out.Opening.y = -dimensions[3] * kMillimetre; // a width of 0 means round, of that diameter
    out.Opening.x = out.Opening.y;
  }
  const std::string problem = PhotometricProblem(out);
  return problem.empty() ? problem : name + ": " + problem;
}

} // namespace radiosity
