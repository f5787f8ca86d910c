// Processes that solve one scene together (the ranks of an MPI job), each computing the
// transport to its own share of the receivers. The core knows no MPI: the caller gives it
// one collective, an element-wise sum over the ranks, and the core does the rest with it.
#ifndef RadiosityCore_ProcessGroup_h
#define RadiosityCore_ProcessGroup_h

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace radiosity
{


struct ProcessGroup
{
  int Rank = 0;
  int Ranks = 1;
  /// Replaces `values[0..count)` on every rank by their sum over the ranks (MPI_Allreduce
  /// with MPI_SUM). Every rank calls it at the same points with the same count.
  std::function<void(double* values, std::size_t count)> SumAll;

  bool Distributed() const { return Ranks > 1 && static_cast<bool>(SumAll); }
};

/// The group's collective with a count of its traffic, for the solver's statistics.
class Collective
{
public:
  explicit Collective(const ProcessGroup& group)
    : Group(group)
  {
  }

  bool Distributed() const { return Group.Distributed(); }
  int Rank() const { return Distributed() ? Group.Rank : 0; }
  int Ranks() const { return Distributed() ? Group.Ranks : 1; }

  /// Sums in place over the ranks; nothing to do for one process.
  void Sum(double* values, std::size_t count)
  {
    if (!Distributed() || count == 0)
    {
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    Group.SumAll(values, count);
    Seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++Calls;
    Bytes += static_cast<double>(count * sizeof(double));
  }
  void Sum(std::vector<double>& values) { Sum(values.data(), values.size()); }

  long long Calls = 0; ///< sums made
  double Bytes = 0;    ///< bytes each rank contributed to them
  /// Time spent in them: the transfers, and waiting for slower ranks.
  double Seconds = 0;

private:
  const ProcessGroup& Group;
};

/// The ranks' verdict on a step that may fail on some ranks only (memory, say): `mine` where
/// this rank failed, "another rank <otherwise>" where only others did, else empty. Every
/// rank calls it, so all go on together or all stop, none left waiting in a later sum.
std::string AgreeOnFailure(const ProcessGroup& group, const std::string& mine, const std::string& otherwise);

/// The largest of every rank's `mine` (each rank calls it at the same point); `mine` for one
/// process. For decisions each rank would take from its own clock.
double LargestOverRanks(const ProcessGroup& group, double mine);

} // namespace radiosity

#endif
