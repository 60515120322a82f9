/**
 * @file   vtkOpenMeshNormalsWeightings.h
 * @brief  vtkOpenMeshNormals' vertex weightings, one functor each (private)
 *
 * A vertex's normal is the sum of its corners' contributions (see
 * docs/normals.md, "Vertex weightings"). For a triangle, the cross product
 * of the two edges at any corner is the face's Newell vector N, so every
 * weighting is a number per corner times the unit face normal:
 * TriangleCornerWeight(|N|, e1, e2) gives that number, computed once per
 * execution with the face normals. Polygons take the general formula:
 * AddPolygonCorner adds the corner's contribution to its vertex's sum.
 * CornerContribution picks between the two for each corner.
 *
 * Neither wrapped nor installed.
 */

#ifndef vtkOpenMeshNormalsWeightings_h
#define vtkOpenMeshNormalsWeightings_h

#include "vtkOpenMeshNormals.h"
#include "vtkOpenMeshNormalsExecution.h"
#include "vtkOpenMeshNormalsTopology.h"

namespace vtkOpenMeshNormalsDetail
{
inline void AddScaled(double weight, const Vector& n, Vector& sum)
{
  sum[0] += weight * n[0];
  sum[1] += weight * n[1];
  sum[2] += weight * n[2];
}

// A weight that overflowed or divided by zero adds nothing.
inline void AddScaledIfFinite(double weight, const Vector& n, Vector& sum)
{
  if (std::isfinite(weight))
  {
    AddScaled(weight, n, sum);
  }
}

// A face's unit normal from its Newell vector (twice its area times the unit normal), as
// every path stores it: valid where its corners are finite and its area is not zero.
struct FaceNormal
{
  Vector Unit;
  double Length;
  bool Valid;
};

inline FaceNormal MakeFaceNormal(const Vector& newell, bool finite)
{
  const double length = std::sqrt(Dot(newell, newell));
  const bool valid = finite && length > 0.0 && std::isfinite(length);
  const double scale = valid ? 1.0 / length : 0.0;
  return { { scale * newell[0], scale * newell[1], scale * newell[2] }, length, valid };
}

// The weight of corner k of the triangle with corners p (and normal face), in float as the
// paths keep it: 0 for a face without a normal or a weight that overflowed.
template <typename Weighting>
float TriangleCornerWeightAt(const double* const p[3], int k, const FaceNormal& face)
{
  double weight = 0.0;
  if (face.Valid)
  {
    weight = Weighting::TriangleCornerWeight(
      face.Length, Subtract(p[(k + 1) % 3], p[k]), Subtract(p[(k + 2) % 3], p[k]));
    weight = std::isfinite(weight) ? weight : 0.0;
  }
  return static_cast<float>(weight);
}

// A polygon's corner as the weightings see it: its face's unit normal,
// Newell length and sign, and the corner's two edges, each computed only if
// the weighting asks for it.
class PolygonCorner
{
public:
  PolygonCorner(const vtkOpenMeshNormalsTopology& topology,
    const vtkOpenMeshNormalsWorkspace& workspace, const double* positions, Index corner, Index face)
    : Topology(topology)
    , Workspace(workspace)
    , Positions(positions)
    , Corner(corner)
    , Face(face)
  {
  }
  const Vector& UnitNormal() const { return this->Workspace.UnitNormal[this->Face]; }
  double FaceLength() const { return this->Workspace.FaceLength[this->Face]; }
  signed char FaceSign() const { return this->Workspace.FaceSign[this->Face]; }
  // From the corner's point to the next corner's, and to the previous one's.
  Vector NextEdge() const
  {
    return Subtract(this->Position(this->Topology.Faces.Next(this->Corner, this->Face)),
      this->Position(this->Corner));
  }
  Vector PreviousEdge() const
  {
    return Subtract(this->Position(this->Topology.Faces.Previous(this->Corner, this->Face)),
      this->Position(this->Corner));
  }

private:
  const double* Position(Index c) const
  {
    return this->Positions + 3 * this->Topology.FaceVertex[c];
  }

  const vtkOpenMeshNormalsTopology& Topology;
  const vtkOpenMeshNormalsWorkspace& Workspace;
  const double* Positions;
  const Index Corner;
  const Index Face;
};

/// Uniform (Gouraud 1971): every face around the vertex counts once.
struct UniformWeighting
{
  static double TriangleCornerWeight(double, const Vector&, const Vector&) { return 1.0; }
  static void AddPolygonCorner(const PolygonCorner& corner, Vector& sum)
  {
    AddScaledIfFinite(1.0, corner.UnitNormal(), sum);
  }
};

/// Area: each face by its area (half its Newell length).
struct AreaWeighting
{
  static double TriangleCornerWeight(double length, const Vector&, const Vector&)
  {
    return 0.5 * length;
  }
  static void AddPolygonCorner(const PolygonCorner& corner, Vector& sum)
  {
    AddScaledIfFinite(0.5 * corner.FaceLength(), corner.UnitNormal(), sum);
  }
};

/// Angle (Thurmer and Wuthrich 1998): each face by its angle at the vertex.
struct AngleWeighting
{
  static double TriangleCornerWeight(double length, const Vector& e1, const Vector& e2)
  {
    return std::atan2(length, Dot(e1, e2));
  }
  static void AddPolygonCorner(const PolygonCorner& corner, Vector& sum)
  {
    const Vector e1 = corner.NextEdge();
    const Vector e2 = corner.PreviousEdge();
    const Vector c = Cross(e1, e2);
    AddScaledIfFinite(std::atan2(std::sqrt(Dot(c, c)), Dot(e1, e2)), corner.UnitNormal(), sum);
  }
};

/// Max (Max 1999): (e1 x e2) / (|e1|^2 |e2|^2), exact on a sphere. A polygon's
/// corner uses its own cross product, turned with the face.
struct MaxWeighting
{
  static double TriangleCornerWeight(double length, const Vector& e1, const Vector& e2)
  {
    return length / (Dot(e1, e1) * Dot(e2, e2));
  }
  static void AddPolygonCorner(const PolygonCorner& corner, Vector& sum)
  {
    const Vector e1 = corner.NextEdge();
    const Vector e2 = corner.PreviousEdge();
    const Vector c = Cross(e1, e2);
    const double scale = Dot(e1, e1) * Dot(e2, e2);
    if (scale > 0.0 && std::isfinite(scale))
    {
      AddScaled(corner.FaceSign() / scale, c, sum);
    }
  }
};

// Calls run with the functor of the weighting, so that the loops over
// corners are compiled once per weighting.
template <typename Run>
void WithWeighting(int weighting, Run&& run)
{
  switch (weighting)
  {
    case vtkOpenMeshNormals::Uniform:
      run(UniformWeighting());
      break;
    case vtkOpenMeshNormals::Area:
      run(AreaWeighting());
      break;
    case vtkOpenMeshNormals::Angle:
      run(AngleWeighting());
      break;
    case vtkOpenMeshNormals::Max:
    default:
      run(MaxWeighting());
      break;
  }
}

// The weighted contribution of a corner to its vertex's normal. Degenerate
// and non-finite faces give nothing (their triangle weights are 0).
template <typename Weighting>
class CornerContribution
{
public:
  CornerContribution(Weighting, const vtkOpenMeshNormalsTopology& topology,
    const vtkOpenMeshNormalsWorkspace& workspace, const double* positions)
    : Topology(topology)
    , Workspace(workspace)
    , Positions(positions)
    , Triangles(topology.Faces.AllTriangles)
  {
  }

  void operator()(Index corner, Vector& sum) const
  {
    const Index f = this->Topology.CornerFace[corner];
    if (this->Triangles)
    {
      AddScaled(this->Workspace.CornerWeight[corner], this->Workspace.UnitNormal[f], sum);
      return;
    }
    if (!this->Workspace.FaceValid[f])
    {
      return;
    }
    Weighting::AddPolygonCorner(
      PolygonCorner(this->Topology, this->Workspace, this->Positions, corner, f), sum);
  }

private:
  const vtkOpenMeshNormalsTopology& Topology;
  const vtkOpenMeshNormalsWorkspace& Workspace;
  const double* Positions;
  const bool Triangles;
};
}

#endif
