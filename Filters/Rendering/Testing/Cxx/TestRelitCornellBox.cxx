// Regression image of the relit Cornell box: mesher -> light-tagged solver -> relight,
// rendered by VTK with the radiosity as unlit vertex colors.
#include "CornellScene.h"

#include "vtkPolyDataMapper.h"
#include "vtkRadiosityRelight.h"
#include "vtkRegressionTestImage.h"

int TestRelitCornellBox(int argc, char* argv[])
{
  vtkSmartPointer<vtkLightTaggedRadiosity> solver = SolvedCornellBox(argc, argv);
  vtkNew<vtkRadiosityRelight> relight;
  relight->SetInputConnection(solver->GetOutputPort());
  relight->SetLightColor(0, 1.0, 0.85, 0.6);
  relight->Update();
  if (relight->GetOutput()->GetNumberOfCells() == 0)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(relight->GetOutputPort());
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  vtkSmartPointer<vtkRenderWindow> window = CornellView(mapper);
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
