#include "Mesh/Surfaces.h"
#include "Geometry/Polygon.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace radiosity
{

SurfaceAssembly::SurfaceAssembly(double quantum, double noise, const Vec3& centre, const MesherOptions& options,
  const std::vector<PolygonPlane>& planes)
  : Quantum(quantum)
  , Noise(noise)
  , Centre(centre)
  , Options(options)
  // Offsets within a millionth of the scene (as before noise was counted), or within the
  // noise of two centroids far from the origin.
  , Groups(GroupCoplanar(planes, std::max(quantum * 1000, 2 * noise), centre))
{
  for (int founder : Groups.Founder)
  {
    Planes.push_back(Plane{ planes[founder].Normal, Dot(planes[founder].Normal, planes[founder].Centroid - centre) });
  }
}

void SurfaceAssembly::Add(
  const std::vector<Vec3>& loop, const Piece& piece, int polygon, int source, const std::vector<Vec3>& outline)
{
  const int s = SurfaceOf(polygon, loop, outline);
  const std::pair<int, int> patches = PatchesOf(s, loop, piece);
  Stitch(s, piece, polygon, source, patches.first);
  Patches += patches.second;
}

int SurfaceAssembly::SurfaceOf(int polygon, const std::vector<Vec3>& loop, const std::vector<Vec3>& outline)
{
  const int s = Groups.Group[polygon];
  assert(s <= static_cast<int>(Meshes.size()) && "polygons are added in the list's order");
  if (s == static_cast<int>(Meshes.size())) // groups are numbered as polygons first meet them
  {
    Meshes.emplace_back();
    Welds.emplace_back();
    // The sharing grid hangs from the surface's first polygon, not from world axes, so a
    // moved or rotated scene groups its small polygons the same way.
    const Vec3& normal = Planes[s].Normal;
    const std::vector<Vec3>& hang = outline.size() >= 3 ? outline : loop;
    const Vec3 edge = hang[1] - hang[0];
    const Vec3 t = Normalized(edge - normal * Dot(edge, normal));
    GridFrames.push_back({ hang[0], t, Cross(normal, t) });
  }
  return s;
}

std::pair<int, int> SurfaceAssembly::PatchesOf(int surface, const std::vector<Vec3>& loop, const Piece& piece)
{
  // A model's many small parts would otherwise each be a shooter (a house's 16k polygons
  // made 59k patches).
  if (!Options.SharePatches || piece.PatchCount != 1)
  {
    return { Patches, piece.PatchCount };
  }
  const std::array<Vec3, 3>& frame = GridFrames[surface];
  const Vec3 c = PolygonCentroid(loop.data(), static_cast<int>(loop.size())) - frame[0];
  // Models space their parts in whole patch sizes, so centroids fall on cell borders: the
  // cells start a millionth early, or float rounding would pick either side.
  auto cellOf = [&](double along) { return static_cast<long long>(std::floor(along / Options.PatchSize + 1e-6)); };
  const auto cell = std::make_tuple(surface, cellOf(Dot(c, frame[1])), cellOf(Dot(c, frame[2])));
  const auto shared = SharedPatch.emplace(cell, Patches);
  return { shared.first->second, shared.second ? 1 : 0 };
}

void SurfaceAssembly::Stitch(int surface, const Piece& piece, int polygon, int source, int firstPatch)
{
  SurfaceMesh& mesh = Meshes[surface];
  size_t corner = 0;
  for (size_t e = 0; e < piece.Sides.size(); ++e)
  {
    std::vector<SurfaceMesh::VertexHandle> handles;
    for (int v = 0; v < piece.Sides[e]; ++v, ++corner)
    {
      const Vec3& p = piece.Corners[corner];
      const std::array<long long, 3> key = QuantizedPoint(p, Quantum);
      auto weld = Welds[surface].find(key);
      if (weld == Welds[surface].end())
      {
        weld = Welds[surface].emplace(key, mesh.add_vertex(SurfaceMesh::Point(p.x, p.y, p.z))).first;
      }
      handles.push_back(weld->second);
    }
    // OpenMesh prints each refusal; the fallback below is the answer to it.
    omerr().disable();
    SurfaceMesh::FaceHandle face = mesh.add_face(handles);
    omerr().enable();
    if (!face.is_valid())
    {
      // Overlapping input (coincident faces, T-shaped junctions of three faces on one
      // edge; a model's parts overlapping by a millimetre, cut along the same contact
      // lines) is not a 2-manifold: give the element its own vertices instead.
      for (auto& h : handles)
      {
        const auto p = mesh.point(h);
        h = mesh.add_vertex(p);
      }
      face = mesh.add_face(handles);
    }
    mesh.data(face).Source = source;
    mesh.data(face).Polygon = polygon;
    mesh.data(face).Patch = firstPatch + piece.LocalPatch[e];
  }
}

void SurfaceAssembly::Flatten(MeshedPolygons& out) const
{
  // Patch ids of empty lattice cells are never used.
  std::map<int, int> compact;
  for (size_t s = 0; s < Meshes.size(); ++s)
  {
    const SurfaceMesh& mesh = Meshes[s];
    const Plane& plane = Planes[s];
    const int base = static_cast<int>(out.Points.size());
    for (auto v : mesh.vertices())
    {
      // Onto the surface's plane where it is off by noise: float input far from the origin
      // puts corners a float step off it, and the solver's tests of what is flat (a patch, a
      // plane that blocks nothing) are relative to the scene, far finer than that step. A
      // point off by more stays (a slightly bent polygon's corner, shared with a neighbour
      // of another plane: moving it would open a crack).
      const auto q = mesh.point(v);
      const Vec3 p{ q[0], q[1], q[2] };
      const double off = Dot(plane.Normal, p - Centre) - plane.Offset;
      out.Points.push_back(std::fabs(off) <= 4 * Noise ? p - plane.Normal * off : p);
    }
    for (auto face : mesh.faces())
    {
      for (auto v : mesh.fv_range(face))
      {
        out.Connectivity.push_back(base + v.idx());
      }
      out.Offsets.push_back(static_cast<int>(out.Connectivity.size()));
      out.SourcePolygon.push_back(mesh.data(face).Source);
      out.MeshedPolygon.push_back(mesh.data(face).Polygon);
      out.PatchId.push_back(compact.emplace(mesh.data(face).Patch, static_cast<int>(compact.size())).first->second);
    }
  }
  out.Patches = static_cast<int>(compact.size());
}

} // namespace radiosity
