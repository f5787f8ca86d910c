// What the rendering tests share: the Cornell box solved once, and a window that shows it
// through the camera of the Cornell data (35 mm lens on 25 mm film).
#ifndef CornellScene_h
#define CornellScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLightTaggedRadiosity.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRadiosityMesher.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTestUtilities.h"
#include "vtkXMLPolyDataReader.h"

/// The light-tagged solver on the Cornell box (mm): 100 mm patches, 25 mm elements.
inline vtkSmartPointer<vtkLightTaggedRadiosity> SolvedCornellBox(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "cornell_box.vtp");
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file);
  delete[] file;
  vtkNew<vtkRadiosityMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetPatchSize(100.0);
  mesher->SetElementSize(25.0);
  auto solver = vtkSmartPointer<vtkLightTaggedRadiosity>::New();
  solver->SetInputConnection(mesher->GetOutputPort());
  solver->SetConvergenceThreshold(2e-3);
  solver->Update();
  return solver;
}

/// A 300 x 300 window showing `mapper` unlit (ambient 1, diffuse 0), rendered once.
inline vtkSmartPointer<vtkRenderWindow> CornellView(vtkMapper* mapper)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->AddRenderer(renderer);
  window->SetSize(300, 300);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(278, 273, -800);
  camera->SetFocalPoint(278, 273, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(39.3);
  renderer->ResetCameraClippingRange();
  window->Render();
  return window;
}

#endif
