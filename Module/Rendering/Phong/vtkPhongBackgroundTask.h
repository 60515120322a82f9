/**
 * @class   vtkPhongBackgroundTask
 * @brief   one piece of a mapper's analysis run on a thread of its own (private)
 *
 * The analyses vtkPhong makes once per upload of a large mesh (whether it is closed,
 * vtkPhongClosedSurface; its occlusion clusters, vtkPhongVisibleClusters) cost about 0.3 s a
 * million triangles. From LargeTriangles on they run here, on copies of what they read, so
 * that the frames drawn meanwhile are drawn as stock VTK draws them, without what the
 * analysis gives; the first frame after it ends uses it. The work must touch nothing but
 * its own copies and its results; out of memory, it gives none (std::bad_alloc is caught).
 * The destructor waits for the thread.
 */

#ifndef vtkPhongBackgroundTask_h
#define vtkPhongBackgroundTask_h

#include <atomic>     // for std::atomic
#include <cstddef>    // for size_t
#include <functional> // for std::function
#include <thread>     // for std::thread

class vtkPhongBackgroundTask
{
public:
  /**
   * From this many triangles on, an analysis runs in the background.
   */
  static constexpr size_t LargeTriangles = size_t(1) << 18;

  explicit vtkPhongBackgroundTask(std::function<void()> work);
  ~vtkPhongBackgroundTask();
  vtkPhongBackgroundTask(const vtkPhongBackgroundTask&) = delete;
  vtkPhongBackgroundTask& operator=(const vtkPhongBackgroundTask&) = delete;

  /**
   * Whether the work has ended (its results may be read then).
   */
  bool IsDone() const;

  /**
   * Block until the work has ended.
   */
  void Wait();

private:
  std::atomic<bool> Done{ false };
  std::thread Thread;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongBackgroundTask.h
