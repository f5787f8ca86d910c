// The moving-light patch basis (paper 2.4): one unit-emission solution per patch, solved in
// one light-tagged pass, stored per element or, for large scenes, per patch node.
#ifndef RadiosityCore_PatchBasis_h
#define RadiosityCore_PatchBasis_h

#include "Solve/RadiositySolver.h"
#include "Base/WorkerPool.h"

#include <string>
#include <vector>

namespace radiosity
{

/// Where the basis is solved and stored.
enum class BasisLevel
{
  /// Elements while the basis fits ElementBasisBudget bytes, otherwise Patches.
  Auto = 0,
  /// Every element a receiver: elements x patches values, exact to the solver.
  Elements = 1,
  /// Every patch one receiver (its outline one polygon), then interpolated linearly to
  /// the elements through the patch's nodes (corners shared with coplanar neighbours, and
  /// the centre, which keeps the patch's mean): about 6 x patches^2 values, independent of
  /// the element count. Indirect light is smooth, so little is lost; contact shadows in
  /// the interreflection blur to patch size.
  Patches = 2
};

/// Auto's limit for an element-level basis: 256 MB.
constexpr double ElementBasisBudget = 256.0 * 1024 * 1024;
/// No basis beyond this: the scene needs larger patches.
constexpr double MaximumBasisBytes = 8.0 * 1024 * 1024 * 1024;

/// The basis convention: Values[r * 3P + 3q + c] is receiver r's radiosity in channel c
/// when patch q emits unit exitance, WITHOUT q's own emission (only light reflected by the
/// scene, including by q's elements). Receivers are the elements (Node empty) or patch
/// nodes; then element e's value is sum_j Weight[3e + j] * row Node[3e + j].
struct PatchBasis
{
  int Patches = 0;
  int Receivers = 0;
  std::vector<float> Values;
  std::vector<int> Node;
  std::vector<float> Weight;
  double Bytes() const { return 4.0 * (Values.size() + Node.size() + Weight.size()); }
};

/// A read-only look at a basis held elsewhere (a VTK array): the same layout.
struct BasisView
{
  int Patches = 0;
  int Receivers = 0;
  const float* Values = nullptr;
  const int* Node = nullptr; ///< null: receivers are the elements
  const float* Weight = nullptr;
};

inline BasisView View(const PatchBasis& b)
{
  return { b.Patches, b.Receivers, b.Values.data(), b.Node.empty() ? nullptr : b.Node.data(),
    b.Weight.empty() ? nullptr : b.Weight.data() };
}

/// The level Auto picks for `elements` and `patches`.
BasisLevel ResolveBasisLevel(BasisLevel level, long long elements, long long patches);

/// Solves the basis into `basis`: every patch a unit emitter (all P solutions in one
/// light-tagged pass), its own emission then removed. Returns an empty string, or why
/// there is no basis (it would pass MaximumBasisBytes or the memory there is, or the
/// solve was aborted); then `basis` is empty.
std::string SolvePatchBasis(const RadiositySolver& solver, const SceneMesh& mesh, const SolverOptions& options,
  BasisLevel level, SolverStatistics& stats, PatchBasis& basis);

/// Records a solved basis in the effect rows of the solution it was built beside (the
/// MovingLightBasis row DescribeEffects leaves last): its size and the shots it took.
void RecordBasisEffect(const PatchBasis& basis, const SolverStatistics& stats, std::vector<EffectDecision>& effects);

/// The frame's result: B_e = D_e + sum_q E_q * basis_q(e), E_q = area mean of D over patch
/// q, where D (the direct part) already contains each patch's first reflection.
void AddBasisInterreflection(const SceneGeometry& geometry, const std::vector<Vec3>& direct,
  const BasisView& basis, const WorkerPool& pool, std::vector<Vec3>& result);

} // namespace radiosity

#endif
