// Actors that draw through an internal one: vtkFollower (vedo 2023's meshes) and vtkLODActor
// hand the mapper an actor of their own that has no mapper, so no bounds (ParaView's
// vtkPVLODActor gives its internal actor the mapper). TestPhongErrorBudget and
// TestPhongLightCulling check that the mapper decides for them as for a vtkActor.

#ifndef vtkPhongTestActors_h
#define vtkPhongTestActors_h

#include "vtkActor.h"
#include "vtkFollower.h"
#include "vtkLODActor.h"
#include "vtkSmartPointer.h"

namespace vtkPhongTest
{
enum class ActorKind
{
  Plain,    // vtkActor
  Follower, // vtkFollower, without a camera to follow: placed as a vtkActor
  LOD       // vtkLODActor, given the time to draw its own mapper (its first render copies the
            // mapper into its LOD mappers, whose VTK 9.1 copy prints VTK's deprecation warnings)
};

inline const char* ActorKindName(ActorKind kind)
{
  return kind == ActorKind::Follower ? "vtkFollower"
    : kind == ActorKind::LOD         ? "vtkLODActor"
                                     : "vtkActor";
}

inline vtkSmartPointer<vtkActor> MakeActor(ActorKind kind)
{
  if (kind == ActorKind::Follower)
  {
    return vtkSmartPointer<vtkFollower>::New();
  }
  if (kind == ActorKind::LOD)
  {
    return vtkSmartPointer<vtkLODActor>::New();
  }
  return vtkSmartPointer<vtkActor>::New();
}
}

#endif
