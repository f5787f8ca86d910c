#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPieces.h"

#include "vtkInformationVector.h"
#include "vtkPolyData.h"

int vtkRadiosityAlgorithm::RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  Run run;
  run.Input = this->GetNumberOfInputPorts() > 0 ? this->InputOf(inputs) : nullptr;
  run.Output = vtkPolyData::GetData(outputs, 0);
  run.Parallel = vtkRadiosityPieces::Parallel(outputs->GetInformationObject(0));
  run.Inputs = inputs;
  run.Outputs = outputs;
  this->BeforeRun(run);
  return vtkRadiosityAdapter::Guarded(this, this->GuardsInput(run) ? run.Input.Get() : nullptr, run.Output,
    [&]() -> int { return this->Execute(run); }, this->AgreesAcrossRanks() ? run.Parallel : nullptr);
}

vtkSmartPointer<vtkPolyData> vtkRadiosityAlgorithm::InputOf(vtkInformationVector** inputs)
{
  return vtkPolyData::GetData(inputs[0]);
}

bool vtkRadiosityAlgorithm::GuardsInput(const Run&)
{
  return true;
}
