// Regression image of the relit Cornell box: mesher -> light-tagged solver -> relight,
// rendered by VTK with the radiosity as unlit vertex colours.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLightTaggedRadiosity.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRadiosityMesher.h"
#include "vtkRadiosityRelight.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkXMLPolyDataReader.h"

int TestRelitCornellBox(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "cornell_box.vtp");
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file);
  delete[] file;

  vtkNew<vtkRadiosityMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetPatchSize(100.0); // millimetres
  mesher->SetElementSize(25.0);
  vtkNew<vtkLightTaggedRadiosity> solver;
  solver->SetInputConnection(mesher->GetOutputPort());
  solver->SetConvergenceThreshold(2e-3);
  vtkNew<vtkRadiosityRelight> relight;
  relight->SetInputConnection(solver->GetOutputPort());
  relight->SetLightColor(0, 1.0, 0.85, 0.6);
  relight->SetLightIntensity(0, 12.0);
  relight->Update();
  if (relight->GetOutput()->GetNumberOfCells() == 0)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(relight->GetOutputPort());
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(300, 300);
  // The Cornell data's camera: 35 mm lens on 25 mm film.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(278, 273, -800);
  camera->SetFocalPoint(278, 273, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(39.3);
  renderer->ResetCameraClippingRange();
  window->Render();

  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
