#include "vtkRadiosityAppendPieces.h"

#include "vtkFieldData.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkRadiosityAppendPieces);

int vtkRadiosityAppendPieces::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkPolyData* first = nullptr;
  for (bool byCells : { true, false })
  {
    for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects() && !first; ++i)
    {
      vtkPolyData* piece = vtkPolyData::GetData(inputVector[0], i);
      first = piece && (byCells ? piece->GetNumberOfCells() : piece->GetNumberOfPoints()) > 0 ? piece : nullptr;
    }
  }
  if (first)
  {
    vtkNew<vtkFieldData> fields; // a copy: the input's arrays are shared, not the container
    fields->ShallowCopy(first->GetFieldData());
    vtkPolyData::GetData(outputVector)->SetFieldData(fields);
  }
  return 1;
}
