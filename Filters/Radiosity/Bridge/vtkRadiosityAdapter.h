// Conversions between vtkPolyData and the VTK-free core's SceneMesh (not wrapped).
#ifndef vtkRadiosityAdapter_h
#define vtkRadiosityAdapter_h

#include "Geometry/Scene.h"

#include <memory>
#include <string>
#include <vector>

#include <functional>

namespace radiosity
{
class WorkerPool;
}

class vtkAlgorithm;
class vtkDataArray;
class vtkDataObject;
class vtkFieldData;
class vtkMultiProcessController;
class vtkObject;
class vtkPolyData;

namespace vtkRadiosityAdapter
{

/// Points and polygons of `input` into `mesh` (arrays left empty). Fails with a message
/// if the input has vertices, lines or strips, since cell data would no longer line up.
bool CopyPolygons(vtkPolyData* input, radiosity::SceneMesh& mesh, std::string& error);
/// The field array that carries SceneMesh::PointQuantum past the mesher.
constexpr const char* PointQuantumName = "PointQuantum";
/// The field array a model set in a room or on a ground carries (relight.in_room): its own
/// span, which the mesher suggests sizes from instead of the whole scene's.
constexpr const char* SizingSpanName = "SizingSpan";
/// The SizingSpan of `input`, 0 where it has none (or not a positive finite one).
double SizingSpan(vtkDataObject* input);
/// SceneMesh::PointQuantum of `input`: its PointQuantum field, or from its points' type.
double PointQuantum(vtkPolyData* input, double farthest);

/// A cell array with the given name, checked for component count (and integral values if
/// `integral`); returns nullptr with a message naming the array and the problem.
vtkDataArray* RequireCellArray(vtkPolyData* input, const char* name, int components,
  bool integral, std::string& error);

/// Reads Reflectance, LightId, optional PatchId; optional Emission into `emission`.
bool ReadSceneArrays(vtkPolyData* input, radiosity::SceneMesh& mesh,
  std::vector<radiosity::Vec3>& emission, std::string& error);

/// Adds (replaces) the string array `name` holding `values` to `fields`.
void AddStrings(vtkFieldData* fields, const char* name, const std::vector<std::string>& values);

/// `count` names from the field array LightNames, or Light<i> for missing ones.
std::vector<std::string> LightNames(vtkFieldData* fields, int count);

/// The threads to use: `asked` when above 0; else VTK's SMP thread count where its backend
/// runs threads (ParaView's Settings, Number of threads), else 0: every hardware thread
/// (the Sequential backend, Debian's, would otherwise mean one).
int Threads(int asked);

/// One worker pool for the relight filter's per-frame work (combining lights, moving
/// lights): threads start once, not per frame, and again only when Threads(0) changes.
/// Hold the pointer while using the pool: a change of setting replaces it.
std::shared_ptr<const radiosity::WorkerPool> SharedPool();

/// Field array on the empty output of a filter that failed.
constexpr const char* FailureMarker = "RadiosityFailed";

/// True if `input` is the marked, empty output of a failed filter upstream.
bool FailedUpstream(vtkDataObject* input);

/// Runs `work` and returns its error (empty when it succeeded), an exception turned into
/// the same words Guarded uses: for work that must reach a collective afterwards on MPI,
/// where an exception escaping one rank would leave the others waiting.
std::string Caught(const std::function<std::string()>& work);

/// Runs a filter's work so that no C++ exception reaches Python or ParaView, and returns
/// what RequestData returns: 1, or 0 when the work failed, as VTK filters do (the executive
/// then stops the update, so the filters downstream do not run). Running out of memory or
/// any other exception becomes the filter's error. On failure `output` (may be null) is
/// emptied and marked with FailureMarker. An input so marked (a second update of a failed
/// pipeline, or a failed output set as the input) fails with one line that says so. With `ranks` (ParaView's MPI server) the
/// ranks agree: one rank's failure fails them all, so none runs the filters downstream
/// into a collective that the others never reach.
int Guarded(vtkAlgorithm* self, vtkDataObject* input, vtkPolyData* output,
  const std::function<int()>& work, vtkMultiProcessController* ranks = nullptr);

/// Brings a writer's input up to date as vtkWriter::Write does (the whole extent, the
/// writer's WriteData run) and says whether the update went through: false, with the
/// writer's error said, where it has no input or a filter upstream failed and stopped the
/// update before the writer.
bool UpdateForWriting(vtkAlgorithm* writer);

/// The warnings of one filter run: each goes to the output window as usual and is kept,
/// so that the output lists them in its field array Warnings (ParaView's Information
/// panel shows a string array's values).
class WarningList
{
public:
  /// `quiet`: keep the messages for the Warnings array without printing them.
  explicit WarningList(bool quiet = false)
    : Quiet(quiet)
  {
  }
  void Add(vtkObject* self, const std::string& message);
  /// Keeps `message` for the Warnings array without printing it (said elsewhere: another rank).
  void Keep(const std::string& message) { this->Messages.push_back(message); }
  const std::vector<std::string>& GetMessages() const { return this->Messages; }
  /// Sets Warnings on `fields` to the upstream ones it holds plus ours, in a new array so
  /// that the input's (shared by a shallow copy) stays as it was; adds nothing if none.
  /// With `replaceRepeats`, an upstream one that ours repeat (the same text up to its first
  /// ':' or ' (', so element numbers aside) is left out: the solver checks the lights on its
  /// mesh after Mark Lights checked them on the scene.
  void AddTo(vtkFieldData* fields, bool replaceRepeats = false) const;

private:
  bool Quiet;
  std::vector<std::string> Messages;
};

}

#endif
