/**
 * @file    vtkPhongClampedSetter.h
 * @brief   vtkSetClampMacro's behaviour, with NaN refused instead of stored
 *
 * vtkSetClampMacro clamps with comparisons, which NaN passes unchanged: the object then holds
 * NaN and every picture made from it does too. The project's clamped double settings use
 * this instead: NaN is refused with an error naming the setting and the value kept; other
 * values are clamped to [min, max] as vtkSetClampMacro does.
 */

#ifndef vtkPhongClampedSetter_h
#define vtkPhongClampedSetter_h

#include "vtkObject.h"
#include "vtkSetGet.h"

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::isnan

/**
 * Set member to value clamped to [min, max] and call Modified() when it changes; refuse NaN
 * with an error through self. Returns whether the member changed.
 */
inline bool vtkPhongSetClamped(
  vtkObject* self, const char* name, double& member, double value, double min, double max)
{
  if (std::isnan(value))
  {
    vtkErrorWithObjectMacro(self, << name << " must be a number in [" << min << ", " << max
                                  << "]; NaN refused, keeping " << member << ".");
    return false;
  }
  const double clamped = std::min(std::max(value, min), max);
  if (member == clamped)
  {
    return false;
  }
  member = clamped;
  self->Modified();
  return true;
}

#endif
// VTK-HeaderTest-Exclude: vtkPhongClampedSetter.h
