// Analytic form factors (Lambert's contour formula; Baum, Rushmeier & Winget 1989).
#ifndef RadiosityCore_FormFactor_h
#define RadiosityCore_FormFactor_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// F(dA -> A): fraction of the energy leaving a differential area at `point` with unit
/// `normal` that arrives at the planar convex polygon `loop`, ignoring occlusion.
/// The polygon is clipped to the receiver's front half-space first; either loop
/// orientation gives the same (non-negative) value. `scratch` avoids an allocation per call.
double PointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* loop,
  int count, std::vector<Vec3>& scratch);

double PointToPolygonFormFactor(const Vec3& point, const Vec3& normal, const Vec3* loop, int count);

/// The same sum over a set of directed edges (start, end pairs, any order), e.g. the
/// boundary of a planar patch made of many elements: interior edges cancel, so the cost
/// is that of the outline. No clipping: every endpoint must be in the front half-space.
double EdgeSetFormFactor(const Vec3& point, const Vec3& normal, const Vec3* edges, int edgeCount);

/// F(A_from -> A_to) = (1/A_from) * integral over A_from of F(dA -> A_to), by splitting
/// `from` into fan triangles, each into `subdivisions`^2 sub-triangles, evaluating the exact
/// inner integral at each sub-triangle's centroid. The inner integral is exact, so the only
/// error is the outer quadrature (largest next to a shared edge, where it is log-singular).
double PolygonToPolygonFormFactor(const Vec3* from, int fromCount, const Vec3* to, int toCount,
  int subdivisions);

} // namespace radiosity

#endif
