/**
 * @file   vtkOpenMeshNormalsBuffers.h
 * @brief  the index, array and vector types shared by vtkOpenMeshNormals' files (private)
 *
 * vtkOpenMeshNormalsTopology, vtkOpenMeshNormalsExecution and
 * vtkOpenMeshNormalsPointByPoint keep their working arrays in these types and
 * read cell arrays through VisitCells. Neither wrapped nor installed.
 */

#ifndef vtkOpenMeshNormalsBuffers_h
#define vtkOpenMeshNormalsBuffers_h

#include "vtkCellArray.h"

#include <array>
#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace vtkOpenMeshNormalsDetail
{
// Indices of points, faces, corners and halfedges: OpenMesh's handles are
// 32-bit, so is everything the filter keeps.
using Index = int;

// Growing a vector with this allocator leaves plain values uninitialized. The
// filter's large arrays are written by parallel loops right after they are
// sized; value-initializing them first would touch (page-fault) all their
// memory serially on one thread, which for a million triangles costs more
// than the computation.
template <typename T>
struct UninitializedAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U; // default-, not value-initialized
  }
  template <typename U, typename... Arguments>
  void construct(U* p, Arguments&&... arguments)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Arguments>(arguments)...);
  }
};
template <typename T>
using Buffer = std::vector<T, UninitializedAllocator<T>>;

// Geometry is computed in double precision; only the output is float.
using Vector = std::array<double, 3>;

inline Vector Subtract(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline bool IsFinite(const double* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Visits the offsets and connectivity of a vtkCellArray, whatever its
// storage (32- or 64-bit).
template <typename Visit>
void VisitCells(vtkCellArray* cells, Visit&& visit)
{
  if (cells->IsStorage64Bit())
  {
    visit(
      cells->GetOffsetsArray64()->GetPointer(0), cells->GetConnectivityArray64()->GetPointer(0));
  }
  else
  {
    visit(
      cells->GetOffsetsArray32()->GetPointer(0), cells->GetConnectivityArray32()->GetPointer(0));
  }
}
}

/**
 * The short names of the types above, for the filter's private classes
 * (which keep VTK's names, outside the namespace): they derive from this
 * struct, which adds nothing else.
 */
struct vtkOpenMeshNormalsTypes
{
  using Index = vtkOpenMeshNormalsDetail::Index;
  template <typename T>
  using Buffer = vtkOpenMeshNormalsDetail::Buffer<T>;
  using Vector = vtkOpenMeshNormalsDetail::Vector;
};

#endif
