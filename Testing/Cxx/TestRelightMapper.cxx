// The relit Cornell box through the GPU mapper: mesher -> light-tagged solver ->
// vtkRadiosityRelightMapper, compared with the baseline of the CPU path (relight filter +
// DisplayColors, TestRelitCornellBox). Then a light change without touching the
// pipeline: the mapper must not upload again, and the picture must change.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLightTaggedRadiosity.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRadiosityMesher.h"
#include "vtkRadiosityRelightMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestUtilities.h"
#include "vtkXMLPolyDataReader.h"

#include <iostream>

int TestRelightMapper(int argc, char* argv[])
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
  solver->Update();
  if (solver->GetOutput()->GetNumberOfCells() == 0)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkRadiosityRelightMapper> mapper;
  mapper->SetInputConnection(solver->GetOutputPort());
  mapper->SetLightColor(0, 1.0, 0.85, 0.6);
  mapper->SetLightIntensity(0, 12.0);
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
  if (mapper->GetUploadCount() != 1 || *mapper->GetLastProblem())
  {
    std::cerr << "uploads " << mapper->GetUploadCount() << ", problem: " << mapper->GetLastProblem() << "\n";
    return EXIT_FAILURE;
  }
  const vtkMTimeType before = mapper->GetMTime();
  mapper->SetLightIntensity(0, 0.0); // the only light off: the box goes black
  window->Render();
  unsigned char* pixel = window->GetPixelData(150, 150, 150, 150, 0);
  const int lit = pixel[0] + pixel[1] + pixel[2];
  delete[] pixel;
  if (mapper->GetUploadCount() != 1 || mapper->GetMTime() != before || lit != 0)
  {
    std::cerr << "after the light change: uploads " << mapper->GetUploadCount() << ", mapper modified "
              << (mapper->GetMTime() != before) << ", centre pixel sum " << lit << "\n";
    return EXIT_FAILURE;
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
