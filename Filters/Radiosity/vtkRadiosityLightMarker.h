/**
 * @class   vtkRadiosityLightMarker
 * @brief   makes a named light of chosen cells, and adds area lights (rectangles, disks)
 *
 * For scenes whose file has no emissive materials, or the wrong ones. The cells chosen by
 * MaterialPattern (a shell-style pattern, `*` and `?`, matched without case against the
 * field array MaterialNames through the cell array MaterialIds, as the scene reader
 * writes them), by cell id (AddCellId) or by a selection on the second input (in
 * ParaView, the active selection) become the light LightName with Emission. A light of
 * that name already there gains the cells; lights left with no cells are removed and the
 * ids renumbered. Each AddAreaLight appends a rectangle or disk that emits towards its
 * normal (reflectance 0.8), with the same cell and point arrays as the rest of the scene.
 *
 * Cell arrays LightId and Emission and the field array LightNames are created when
 * missing; Reflectance must be there. The output lists the same warnings as the solver
 * does about its lights (wound the wrong way, drawn in another surface's plane) in the
 * field array Warnings. A pattern that matches no material, an id out of range or an
 * area light without a size is an error, and the output is empty.
 *
 * @sa vtkRadiositySceneReader vtkRadiosityMesher
 */
#ifndef vtkRadiosityLightMarker_h
#define vtkRadiosityLightMarker_h

#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityLightMarker : public vtkRadiosityAlgorithm
{
public:
  static vtkRadiosityLightMarker* New();
  vtkTypeMacro(vtkRadiosityLightMarker, vtkRadiosityAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The light the chosen cells become. Default "Light".
  vtkSetStringMacro(LightName);
  vtkGetStringMacro(LightName);
  ///@}

  ///@{
  /// Cells whose material name matches this pattern are chosen (empty: none).
  vtkSetStringMacro(MaterialPattern);
  vtkGetStringMacro(MaterialPattern);
  ///@}

  ///@{
  /// Cells chosen by id.
  void AddCellId(vtkIdType id);
  void ClearCellIds();
  ///@}

  ///@{
  /// The chosen cells' Emission (the light's default color and intensity). Default 1, 1, 1.
  /// Each component finite and at least GetEmissionMinValue(); marking with another is an
  /// error that names it.
  vtkSetVector3Macro(Emission, double);
  vtkGetVector3Macro(Emission, double);
  static double GetEmissionMinValue() { return 0.0; }
  static double GetEmissionMaxValue() { return VTK_DOUBLE_MAX; }
  ///@}

  ///@{
  /// Appends an area light: shape 0 a width x height rectangle, 1 a disk of diameter
  /// width; centre, the normal it emits towards, and its Emission color.
  void AddAreaLight(const char* name, int shape, double cx, double cy, double cz, double nx, double ny,
    double nz, double width, double height, double r, double g, double b);
  void ClearAreaLights();
  ///@}

  ///@{
  /// Appends a luminaire: a light at a point, not a cell. Its kind ("goniometric",
  /// "point", "spot" or "lambertian") and that kind's parameters as "name=value; ..." (a
  /// goniometric one's "file=<IES or EULUMDAT file>; lumens=<the file's own if left
  /// out>", a spot's "cone=30; falloff=5"), its position, the direction it aims (a
  /// downlight's nadir), its rotation about the aim in degrees, and its color. Each is
  /// made once here, so a missing file or a misspelt parameter is an error now; one of
  /// the same name as a luminaire already in the scene replaces it. They travel as field
  /// arrays (LuminaireNames, LuminaireKinds, LuminaireParameters, LuminairePlacement) to
  /// the solver, which gives each a solution of its own.
  void AddLuminaire(const char* name, const char* kind, const char* parameters, double x, double y, double z,
    double ax, double ay, double az, double rotation, double r, double g, double b);
  void ClearLuminaires();
  ///@}

  ///@{
  /// The kinds a luminaire may be, from the core's one registry (LightKinds()): the
  /// panel's Kind list and Python read them here.
  static int GetNumberOfLightKinds();
  static const char* GetLightKindName(int i);
  ///@}

  /// Optional second input: a vtkSelection whose cells are chosen too.
  void SetSelectionConnection(vtkAlgorithmOutput* selection) { this->SetInputConnection(1, selection); }

protected:
  vtkRadiosityLightMarker();
  ~vtkRadiosityLightMarker() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int Execute(const Run& run) override;

private:
  vtkRadiosityLightMarker(const vtkRadiosityLightMarker&) = delete;
  void operator=(const vtkRadiosityLightMarker&) = delete;

  char* LightName = nullptr;
  char* MaterialPattern = nullptr;
  double Emission[3] = { 1, 1, 1 };
  struct Choices;
  std::unique_ptr<Choices> Chosen; ///< cell ids and area lights
};

#endif
