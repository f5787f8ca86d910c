#include "vtkRadiosityAbort.h"

#include "vtkAlgorithm.h"

#include <atomic>

namespace
{
/// Counts abort requests; a watch stops once the count moves past the one it saw.
std::atomic<unsigned> AbortRequests{ 0 };
}

void vtkRadiosityRequestAbort()
{
  ++AbortRequests;
}

vtkRadiosityAbortWatch::vtkRadiosityAbortWatch(vtkAlgorithm* self)
  : Self(self)
  , Generation(AbortRequests.load())
{
  self->SetAbortExecute(0);
}

bool vtkRadiosityAbortWatch::Stop() const
{
  return this->Self->GetAbortExecute() || AbortRequests.load() != this->Generation;
}
