/**
 * @class   vtkRadiosityMesher
 * @brief   splits polygons into radiosity patches and elements
 *
 * Each input polygon (triangle, quad or any simple planar polygon: a concave one is
 * ear-clipped into triangles first) is split into patches with
 * edges at most PatchSize and each patch into elements with edges at most ElementSize
 * (world units). The output polygons are the elements; cell array `PatchId` tells which
 * patch each belongs to, and every input cell array (`Reflectance`, `LightId`, `Emission`,
 * ...) is passed to the elements cut from that cell. Points are shared within a flat
 * surface of one material and duplicated where orientation or material changes, so
 * smoothing radiosity over points never bleeds across a corner.
 *
 * The input needs cell arrays `Reflectance` (3 components) and `LightId` (1 integer
 * component); errors name the missing or malformed array and leave the output empty.
 * The connectivity is built with OpenMesh.
 *
 * @sa vtkLightTaggedRadiosity vtkRadiosityRelight
 */
#ifndef vtkRadiosityMesher_h
#define vtkRadiosityMesher_h

#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityMesher : public vtkRadiosityAlgorithm
{
public:
  static vtkRadiosityMesher* New();
  vtkTypeMacro(vtkRadiosityMesher, vtkRadiosityAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Longest edge of a patch (the shooting unit), in world units. 0 (the default): from
  /// the scene, a sixth of its extent rounded (1 for a 4 x 2.5 x 4 m room, 1000 for the
  /// same room in millimetres), so a script meshes as the GUI does. A sliver triangle
  /// (narrower than a quarter of its length) gets patches of about PatchSize^2 area
  /// instead, so long thin strips do not turn into dozens of empty shooters.
  vtkSetClampMacro(PatchSize, double, 0, VTK_DOUBLE_MAX);
  vtkGetMacro(PatchSize, double);
  ///@}

  ///@{
  /// Longest edge of an element (the receiving unit), in world units. 0 (the default): a
  /// quarter of the patch size in use.
  vtkSetClampMacro(ElementSize, double, 0, VTK_DOUBLE_MAX);
  vtkGetMacro(ElementSize, double);
  ///@}

  ///@{
  /// The sizes the last execution used (the automatic ones resolved; the element size
  /// before any MaximumElements cut, which the field array MesherElementSize reports).
  vtkGetMacro(PatchSizeInUse, double);
  vtkGetMacro(ElementSizeInUse, double);
  /// The sizes the last run meshed with (its field arrays MesherPatchSize and
  /// MesherElementSize; the element coarser than ElementSizeInUse where MaximumElements
  /// asked for it); 0 before a run.
  vtkGetMacro(MesherPatchSize, double);
  vtkGetMacro(MesherElementSize, double);
  ///@}

  ///@{
  /// Join adjacent, flat, same-material triangle pairs that form a convex quad back into
  /// that quad before meshing (a triangulating exporter's split), which then meshes into
  /// a quarter of the elements. Default on; the count is in MergedTrianglePairs.
  vtkSetMacro(MergeTriangles, bool);
  vtkGetMacro(MergeTriangles, bool);
  vtkBooleanMacro(MergeTriangles, bool);
  ///@}

  ///@{
  /// Polygons that fit in one patch share it with the other such polygons of their flat,
  /// same-material surface in the same PatchSize cell, so a model's many small parts do
  /// not each become a shooter. Default on.
  vtkSetMacro(SharePatches, bool);
  vtkGetMacro(SharePatches, bool);
  vtkBooleanMacro(SharePatches, bool);
  ///@}

  ///@{
  /// Small patches of a curved surface (a tessellated CAD part, a scan: each triangle on
  /// its own plane) are grouped into face clusters about 0.6 PatchSize across whose normals
  /// stay within this many degrees, so that the solver shoots from groups of polygons,
  /// not from each one. 0 turns it off; default 30, at most 60.
  vtkSetClampMacro(ClusterAngle, double, 0.0, 60.0);
  vtkGetMacro(ClusterAngle, double);
  ///@}

  ///@{
  /// One setting for what a solve costs and how close it comes: -1 (Custom, the default)
  /// leaves everything to the settings themselves; 0 (Preview) to 4 (Reference) scale
  /// ElementSize (the one given or suggested, at most the patch) and set LampGrading and
  /// ShadowGrading here, and stamp the level on the output (field array Accuracy),
  /// from which the solver takes its GatherRays, ClusterSeparation and GatherSweeps (each
  /// level's numbers: the table in Core/Base/AccuracyLevels.h). Level 2 is the filters'
  /// defaults. What each costs and
  /// buys on a real building: docs/benchmarks.md, "One accuracy knob".
  vtkSetClampMacro(Accuracy, int, -1, 4);
  vtkGetMacro(Accuracy, int);
  /// The level's numbers (relight.levels reads them): element scale, LampGrading,
  /// ShadowGrading, GatherRays, ClusterSeparation, GatherSweeps, and its name.
  static double GetAccuracyElementScale(int level);
  static double GetAccuracyLampGrading(int level);
  static double GetAccuracyShadowGrading(int level);
  static int GetAccuracyGatherRays(int level);
  static double GetAccuracyClusterSeparation(int level);
  static int GetAccuracyGatherSweeps(int level);
  static const char* GetAccuracyName(int level);
  static int GetNumberOfAccuracyLevels();
  /// The LampGrading this filter meshes with: Accuracy's where a level is chosen.
  double GetLampGradingInUse() const;
  ///@}

  ///@{
  /// Finer elements where a lamp lights a surface from up close: at a distance d from the
  /// lamp, elements of LampGrading * d, down to a quarter of ElementSize, so the peak by a
  /// lamp and the shadow edges near it are not spread over a whole element. Quads refine
  /// whole rows and columns of their grid, triangles their whole lattice. 0 turns it off;
  /// default 0.2, at most 2.
  vtkSetClampMacro(LampGrading, double, 0.0, 2.0);
  vtkGetMacro(LampGrading, double);
  ///@}

  ///@{
  /// Finer elements where a shadow's edge crosses a patch a lamp lights (some of its
  /// points see the lamp, others do not: a table's shadow on the floor, a door's head on
  /// the wall under a lamp): elements of ShadowGrading times ElementSize there (down to a
  /// quarter), graded as LampGrading grades and only with it. 0 (default) turns it off;
  /// the Fine and Reference accuracy levels use 0.5.
  vtkSetClampMacro(ShadowGrading, double, 0.0, 1.0);
  vtkGetMacro(ShadowGrading, double);
  /// The ShadowGrading this filter meshes with: Accuracy's where a level is chosen.
  double GetShadowGradingInUse() const;
  ///@}

  ///@{
  /// Element budget. 0 (default): none. Otherwise, when ElementSize would make more
  /// elements than this, the mesher uses the smallest larger element size that fits and
  /// says so; the size used is in the field array MesherElementSize. Without a budget,
  /// more than 2,000,000 elements gives a warning (time and memory) before meshing.
  vtkSetClampMacro(MaximumElements, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumElements, vtkIdType);
  ///@}

  ///@{
  /// Sizes that suit the input whatever its unit and orientation (a sixth of its extent,
  /// rounded; the element a quarter of that), the input's polygon area, and about how
  /// many elements the suggested sizes make. Known once the pipeline information
  /// is updated with the input already executed (in ParaView: when the filter is added
  /// to an applied source); 0 before (the sizes are then picked when the mesher runs).
  /// ParaView starts PatchSize and ElementSize from the suggestions.
  vtkGetMacro(SuggestedPatchSize, double);
  vtkGetMacro(SuggestedElementSize, double);
  vtkGetMacro(InputArea, double);
  vtkGetMacro(SuggestedElements, double);
  ///@}

  /// The number of elements these sizes would make of the input (exact, without meshing;
  /// runs the information pass first, which reads the input again only if it changed):
  /// the Properties panel's live estimate while the sizes are edited, before Apply. A size
  /// of 0 is resolved as PatchSize and ElementSize are.
  double EstimateElements(double patchSize, double elementSize);

protected:
  vtkRadiosityMesher();
  ~vtkRadiosityMesher() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int Execute(const Run& run) override;
  vtkSmartPointer<vtkPolyData> InputOf(vtkInformationVector** inputs) override;
  bool GuardsInput(const Run& run) override;

private:
  vtkRadiosityMesher(const vtkRadiosityMesher&) = delete;
  void operator=(const vtkRadiosityMesher&) = delete;

  double PatchSize = 0.0;
  double ElementSize = 0.0;
  double PatchSizeInUse = 0.0;
  double ElementSizeInUse = 0.0;
  double MesherPatchSize = 0.0;
  double MesherElementSize = 0.0;
  /// The suggested sizes, area and element count for `given` (all 0 where it has no data
  /// yet), once per input.
  void SuggestFor(vtkDataSet* given);
  /// PatchSizeInUse and ElementSizeInUse, given the scene's suggested patch size (0: none).
  void ResolveSizes(double suggestedPatch);
  /// The sizes for this run: the information pass's suggestion for `given` where it made
  /// one (serial runs), else `scenePatch()`, the scene's (on MPI, the whole scene's).
  void ChooseSizes(vtkDataSet* given, bool parallel, const std::function<double()>& scenePatch);
  vtkIdType MaximumElements = 0;
  bool MergeTriangles = true;
  bool SharePatches = true;
  double ClusterAngle = 30;
  double LampGrading = 0.2;
  double ShadowGrading = 0;
  int Accuracy = -1;
  double SuggestedPatchSize = 0.0;
  double SuggestedElementSize = 0.0;
  double InputArea = 0.0;
  double SuggestedElements = 0.0;
  vtkMTimeType SuggestedForInput = 0; ///< the input's time when the suggestion was made
  struct Polygons;
  std::unique_ptr<Polygons> SeenInput; ///< the polygons of that input, for estimates
};

#endif
