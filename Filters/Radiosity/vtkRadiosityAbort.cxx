#include "vtkRadiosityAbort.h"

#include "vtkAlgorithm.h"

#include <atomic>

namespace
{
std::atomic<bool> AbortRequested{ false };
}

void vtkRadiosityRequestAbort()
{
  AbortRequested = true;
}

void vtkRadiosityClearAbort()
{
  AbortRequested = false;
}

vtkRadiosityAbortWatch::vtkRadiosityAbortWatch(vtkAlgorithm* self)
  : Self(self)
{
  self->SetAbortExecute(0);
}

bool vtkRadiosityAbortWatch::Stop() const
{
  return this->Self->GetAbortExecute() || AbortRequested.load();
}
