// What ranks solving together tell each other once per shot: one table with a row
// per rank, summed over the ranks. Each rank fills only its own row, so the sum is exact and
// every rank reads the same table.
#ifndef RadiosityCore_RankTable_h
#define RadiosityCore_RankTable_h

#include "Base/ProcessGroup.h"
#include "Solve/RadiositySolver.h"

#include <vector>

namespace radiosity
{

/// One rank's row: its stop flags, what the last shot delivered to its receivers and their
/// remaining unshot power per solution, and its best patch for the next shot with that
/// patch's power and unshot energy per solution (and the emission part of it, with the
/// direct part kept apart).
template <typename Channel>
struct RankRow
{
  using Value = typename Channel::Value;
  bool OutOfTime = false, Aborted = false;
  double BestPower = -1;
  int Candidate = -1; ///< -1: the rank has no patch left to shoot
  double Received = 0;
  std::vector<double> Remaining;
  std::vector<Value> Unshot, UnshotEmission;
};

template <typename Channel>
class RankTable
{
public:
  using Value = typename Channel::Value;

  RankTable(int solutions, bool direct)
    : L(solutions)
    , Direct(direct)
  {
  }

  /// Puts `mine` in this rank's row and sums the table over the ranks: every rank calls it.
  void Exchange(Collective& ranks, const RankRow<Channel>& mine)
  {
    Table.assign(Row() * ranks.Ranks(), 0.0);
    double* row = &Table[Row() * ranks.Rank()];
    row[0] = mine.OutOfTime ? 1 : 0;
    row[1] = mine.Aborted ? 1 : 0;
    row[2] = mine.BestPower;
    row[3] = mine.Candidate;
    row[4] = mine.Received;
    std::copy(mine.Remaining.begin(), mine.Remaining.end(), row + 5);
    double* values = row + 5 + L;
    const size_t d = Channel::Doubles;
    for (int m = 0; m < L && mine.Candidate >= 0; ++m)
    {
      Channel::Store(mine.Unshot[m], values + m * d);
      if (Direct)
      {
        Channel::Store(mine.UnshotEmission[m], values + (L + m) * d);
      }
    }
    ranks.Sum(Table);
  }

  bool AnyOutOfTime() const { return Column(0) > 0; }
  bool AnyAborted() const { return Column(1) > 0; }
  /// What the last shot delivered to every rank's receivers.
  double Received() const { return Column(4); }
  /// The remaining unshot power of solution m over every rank's receivers.
  double Remaining(int m) const { return Column(5 + m); }

  /// The next shooter: the candidate with the largest power, the lowest patch on ties, with
  /// its unshot energy (only its owner had it). False when no rank has a candidate.
  bool Winner(int& patch, std::vector<Value>& unshot, std::vector<Value>& unshotEmission) const
  {
    const double* winner = nullptr;
    for (size_t r = 0; r < Table.size(); r += Row())
    {
      const double* t = &Table[r];
      if (t[3] >= 0 && (!winner || t[2] > winner[2] || (t[2] == winner[2] && t[3] < winner[3])))
      {
        winner = t;
      }
    }
    if (!winner)
    {
      return false;
    }
    patch = static_cast<int>(winner[3]);
    const double* values = winner + 5 + L;
    const size_t d = Channel::Doubles;
    unshot.resize(L);
    unshotEmission.resize(Direct ? L : 0);
    for (int m = 0; m < L; ++m)
    {
      unshot[m] = Channel::Load(values + m * d);
      if (Direct)
      {
        unshotEmission[m] = Channel::Load(values + (L + m) * d);
      }
    }
    return true;
  }

private:
  size_t Row() const { return 5 + L + L * Channel::Doubles * (Direct ? 2 : 1); }

  /// Entry `i` summed over the rows.
  double Column(size_t i) const
  {
    double sum = 0;
    for (size_t r = 0; r < Table.size(); r += Row())
    {
      sum += Table[r + i];
    }
    return sum;
  }

  const int L;
  const bool Direct;
  std::vector<double> Table;
};

/// After the last shot: every rank's receivers into every rank's output (each wrote its
/// own, zero elsewhere), the work counts summed, and the sums' own cost recorded.
void GatherOverRanks(Collective& ranks, Solution& out);

} // namespace radiosity

#endif
