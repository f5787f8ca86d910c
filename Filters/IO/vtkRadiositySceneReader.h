/**
 * @class   vtkRadiositySceneReader
 * @brief   reads a scene file (OBJ+MTL, glTF/GLB, PLY, VRML; IFC, FBX, DAE, 3DS...
 *          through assimp; the one list is Formats() in Formats/SceneFiles.cxx) into the
 *          radiosity input: polygons with Reflectance, LightId, Emission
 *
 * Diffuse colors (MTL `Kd`, glTF `baseColorFactor` times the base color texture's mean,
 * PLY colors) become the cell array `Reflectance`, clamped into [0, 1] with one warning
 * that names the clamped materials. Emissive colors (MTL `Ke`, glTF `emissiveFactor`
 * times `KHR_materials_emissive_strength`) make lights: one per emissive material, named
 * after it, or with LightsPerObject one per object and emissive material, named after the
 * object; `Emission` is the emissive color. Scene-graph transforms are applied, and
 * UnitScale scales every coordinate (0.001 for a file in millimetres). Degenerate cells
 * (zero area, collinear points, crossing edges) are dropped and counted. The output also
 * keeps each cell's material (cell array `MaterialIds`, field array `MaterialNames`), for
 * marking lights by material later, and a one-line summary (field array `ImportSummary`).
 *
 * A file that cannot be read gives an error naming the file and the problem, and an
 * empty output.
 *
 * @sa vtkRadiosityMesher
 */
#ifndef vtkRadiositySceneReader_h
#define vtkRadiositySceneReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkRadiosityIOModule.h" // for export macro

#include <string> // for GetFileExtensions

class VTKRADIOSITYIO_EXPORT vtkRadiositySceneReader : public vtkPolyDataAlgorithm
{
public:
  static vtkRadiositySceneReader* New();
  vtkTypeMacro(vtkRadiositySceneReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene file; its extension picks the format.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /// Multiplies every coordinate, e.g. 0.001 for a file in millimetres. Default 1.
  vtkSetClampMacro(UnitScale, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(UnitScale, double);
  ///@}

  ///@{
  /// One light per object and emissive material (named after the object) instead of one
  /// per emissive material. Default off.
  vtkSetMacro(LightsPerObject, bool);
  vtkGetMacro(LightsPerObject, bool);
  vtkBooleanMacro(LightsPerObject, bool);
  ///@}

  /// True if the extension is one this reader handles (assimp's only where installed).
  static bool CanReadFile(const char* fileName);
  /// Every extension the reader knows, space-separated (the table in
  /// IO/Formats/SceneFiles.cxx; the ParaView reader hint lists the same).
  static std::string GetFileExtensions();

protected:
  vtkRadiositySceneReader();
  ~vtkRadiositySceneReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkRadiositySceneReader(const vtkRadiositySceneReader&) = delete;
  void operator=(const vtkRadiositySceneReader&) = delete;

  char* FileName = nullptr;
  double UnitScale = 1.0;
  bool LightsPerObject = false;
};

#endif
