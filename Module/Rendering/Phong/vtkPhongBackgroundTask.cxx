#include "vtkPhongBackgroundTask.h"

#include <new>
#include <utility>

//------------------------------------------------------------------------------
vtkPhongBackgroundTask::vtkPhongBackgroundTask(std::function<void()> work)
  : Thread(
      [this, work = std::move(work)]()
      {
        try
        {
          work();
        }
        catch (const std::bad_alloc&)
        {
          // No memory for the analysis: it gives nothing, and the mapper draws without it.
        }
        this->Done.store(true, std::memory_order_release);
      })
{
}

//------------------------------------------------------------------------------
vtkPhongBackgroundTask::~vtkPhongBackgroundTask()
{
  this->Wait();
}

//------------------------------------------------------------------------------
bool vtkPhongBackgroundTask::IsDone() const
{
  return this->Done.load(std::memory_order_acquire);
}

//------------------------------------------------------------------------------
void vtkPhongBackgroundTask::Wait()
{
  if (this->Thread.joinable())
  {
    this->Thread.join();
  }
}
