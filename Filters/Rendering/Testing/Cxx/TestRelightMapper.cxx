// The relit Cornell box through the GPU mapper: mesher -> light-tagged solver ->
// vtkRadiosityRelightMapper, compared with the baseline of the CPU path (relight filter +
// DisplayColors, TestRelitCornellBox). Then a light change without touching the
// pipeline: the mapper must not upload again, and the picture must change.
#include "CornellScene.h"

#include "vtkRadiosityLights.h"
#include "vtkRadiosityRelightMapper.h"
#include "vtkRegressionTestImage.h"

#include <iostream>

int TestRelightMapper(int argc, char* argv[])
{
  vtkSmartPointer<vtkLightTaggedRadiosity> solver = SolvedCornellBox(argc, argv);
  if (solver->GetOutput()->GetNumberOfCells() == 0)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkRadiosityRelightMapper> mapper;
  mapper->SetInputConnection(solver->GetOutputPort());
  mapper->GetLights()->SetLightColor(0, 1.0, 0.85, 0.6);
  vtkSmartPointer<vtkRenderWindow> window = CornellView(mapper);
  const int result = vtkRegressionTestImage(window);
  if (mapper->GetUploadCount() != 1 || *mapper->GetLastProblem())
  {
    std::cerr << "uploads " << mapper->GetUploadCount() << ", problem: " << mapper->GetLastProblem() << "\n";
    return EXIT_FAILURE;
  }
  const vtkMTimeType before = mapper->GetMTime();
  mapper->GetLights()->SetLightIntensity(0, 0.0); // the only light off: the box goes black
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
