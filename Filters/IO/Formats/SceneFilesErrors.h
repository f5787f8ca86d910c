// Keeps a VTK reader's error messages for our own error, instead of the output window.
#ifndef SceneFilesErrors_h
#define SceneFilesErrors_h

#include "vtkCommand.h"
#include "vtkObject.h"
#include "vtkSmartPointer.h"

#include <string>

namespace SceneFiles
{

class ErrorCapture
{
public:
  explicit ErrorCapture(vtkObject* reader);
  ~ErrorCapture();
  /// The first error the reader gave (its text without VTK's file and line), or empty.
  std::string Message() const;

private:
  class Observer;
  vtkObject* Reader;
  vtkSmartPointer<Observer> Command;
  unsigned long Tags[2];
};

}

#endif
