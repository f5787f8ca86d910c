/**
 * @class   vtkRadiosityAppendPieces
 * @brief   appends the pieces of a distributed scene, keeping the scene's field data
 *
 * vtkAppendPolyData drops field data, but a solved scene keeps its lights there
 * (LightNames, LightDefaultColors, the effect reports). This appends its inputs in order and
 * gives the output the field data of the first input with cells (or points). ParaView's
 * writers use it to merge the ranks' pieces on rank 0 (their PostGatherHelper), and the
 * solver to see the whole scene on every rank.
 */
#ifndef vtkRadiosityAppendPieces_h
#define vtkRadiosityAppendPieces_h

#include "vtkAppendPolyData.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

class VTKRADIOSITYFILTERS_EXPORT vtkRadiosityAppendPieces : public vtkAppendPolyData
{
public:
  static vtkRadiosityAppendPieces* New();
  vtkTypeMacro(vtkRadiosityAppendPieces, vtkAppendPolyData);

protected:
  vtkRadiosityAppendPieces() = default;
  ~vtkRadiosityAppendPieces() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkRadiosityAppendPieces(const vtkRadiosityAppendPieces&) = delete;
  void operator=(const vtkRadiosityAppendPieces&) = delete;
};

#endif
