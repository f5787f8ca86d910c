// Face clusters: the tree's form factors against the sum over their polygons, the mesher's
// clusters against their limits, and a room with a tessellated sphere solved through
// clusters against progressive refinement over every triangle.
#include "CurvedRoom.h"
#include "Geometry/ClusterTree.h"
#include "Geometry/FormFactor.h"
#include "Solve/LightSolutions.h"
#include "SceneBuilders.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace radiosity;
using namespace radiosity_scenes;

namespace
{
const Vec3 kSphere{ 0.7, 0.7, 0.65 }; // CurvedRoom's spheres

bool operator!=(const Vec3& a, const Vec3& b)
{
  return a.x != b.x || a.y != b.y || a.z != b.z;
}

/// A cap of a tessellated sphere (radius 1, outward), `triangles` of the whole sphere, the
/// triangles within `degrees` of the north pole.
SceneMesh Cap(int triangles, double degrees)
{
  RoomPolygons r;
  AddSphere(r, { 0, 0, 0 }, 1.0, triangles, { 0.5, 0.5, 0.5 });
  SceneMesh mesh;
  mesh.Points = r.Points;
  for (size_t c = 0; c + 1 < r.Offsets.size(); ++c)
  {
    const Vec3& a = r.Points[r.Connectivity[r.Offsets[c]]];
    if (a.z >= std::cos(degrees * Pi / 180))
    {
      mesh.AddPolygon({ r.Connectivity.begin() + r.Offsets[c], r.Connectivity.begin() + r.Offsets[c + 1] });
      mesh.Reflectance.push_back({ 0.5, 0.5, 0.5 });
      mesh.LightId.push_back(-1);
    }
  }
  return mesh;
}

std::vector<Vec3> Loops(const SceneMesh& mesh)
{
  std::vector<Vec3> loops;
  for (int id : mesh.Connectivity)
  {
    loops.push_back(mesh.Points[id]);
  }
  return loops;
}

double ExactFactor(const SceneMesh& mesh, const SceneGeometry& g, const Vec3& x, const Vec3& n)
{
  double f = 0;
  std::vector<Vec3> loop;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    loop.clear();
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      loop.push_back(mesh.Points[mesh.Polygon(e)[v]]);
    }
    f += Dot(g.Normal[e], x - g.Centroid[e]) > 0 ? PointToPolygonFormFactor(x, n, loop.data(), static_cast<int>(loop.size())) : 0;
  }
  return f;
}

Solution SolveRoom(const SceneMesh& mesh, SolverMethod method, int lamps)
{
  const RadiositySolver solver(mesh);
  EXPECT_TRUE(solver.Error().empty()) << solver.Error();
  SolverOptions o = radiosity_test::Converged(1e-4);
  o.SolverMethod = method;
  return SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::LightTagged, o);
}

/// Per light, sum |a - b| A / sum b A over the elements, where the two meshes' elements are
/// the same polygons in any order: matched by centroid.
double MeanDifference(const SceneMesh& ma, const Solution& a, const SceneMesh& mb, const Solution& b, int light)
{
  const SceneGeometry ga(ma), gb(mb);
  std::map<std::array<long long, 3>, int> where;
  for (int e = 0; e < mb.NumberOfPolygons(); ++e)
  {
    where[QuantizedPoint(gb.Centroid[e], 1e-6)] = e;
  }
  double diff = 0, sum = 0;
  for (int e = 0; e < ma.NumberOfPolygons(); ++e)
  {
    const auto found = where.find(QuantizedPoint(ga.Centroid[e], 1e-6));
    EXPECT_TRUE(found != where.end());
    if (found == where.end())
    {
      continue;
    }
    const Vec3& x = a.Radiosity[static_cast<size_t>(e) * a.Solutions + light];
    const Vec3& y = b.Radiosity[static_cast<size_t>(found->second) * b.Solutions + light];
    diff += (std::fabs(x.x - y.x) + std::fabs(x.y - y.y) + std::fabs(x.z - y.z)) * ga.Area[e];
    sum += (y.x + y.y + y.z) * ga.Area[e];
  }
  return diff / sum;
}
} // namespace

TEST(Clusters, TreeFactorsEqualTheSumOverTheirPolygons)
{
  const SceneMesh cap = Cap(20000, 40);
  const SceneGeometry g(cap);
  std::vector<int> all(cap.NumberOfPolygons());
  for (size_t e = 0; e < all.size(); ++e)
  {
    all[e] = static_cast<int>(e);
  }
  const std::vector<Vec3> loops = Loops(cap);
  const ClusterTree tree(cap, g, loops, all);
  std::vector<Vec3> scratch;
  // Far above, beside at a grazing angle, and near (where the tree must open to its leaves).
  struct Probe
  {
    Vec3 X, N;
    double Tolerance;
  };
  for (const Probe& p : { Probe{ { 0, 0, 8 }, { 0, 0, -1 }, 0.01 }, Probe{ { 3, 0, 1.2 }, Normalized(Vec3{ -1, 0, -0.2 }), 0.02 },
         Probe{ { 0.1, 0, 1.05 }, { 0, 0, -1 }, 0.005 }, Probe{ { 0, 0.4, 1.3 }, Normalized(Vec3{ 0, -1, -1 }), 0.01 } })
  {
    const double exact = ExactFactor(cap, g, p.X, p.N);
    ASSERT_GT(exact, 0);
    EXPECT_NEAR(tree.PointFactor(p.X, p.N, scratch), exact, p.Tolerance * exact);
    // Where the whole cap is in front of the receiver's plane, n . vector is the factor.
    EXPECT_NEAR(Dot(p.N, tree.FactorVector(p.X)), exact, std::max(p.Tolerance, 1e-9) * exact + 1e-12);
  }
  EXPECT_NEAR(tree.Cone().Spread * 180 / Pi, 40, 2.0);
}

TEST(Clusters, PolygonVectorGivesLambertsFactor)
{
  const Vec3 square[4] = { { -1, -1, 2 }, { 1, -1, 2 }, { 1, 1, 2 }, { -1, 1, 2 } };
  for (const Vec3& n : { Vec3{ 0, 0, 1 }, Normalized(Vec3{ 0.2, 0.1, 1 }) })
  {
    const Vec3 x{ 0.1, 0.2, 0 };
    EXPECT_NEAR(Dot(n, PolygonFactorVector(x, square, 4)), PointToPolygonFormFactor(x, n, square, 4), 1e-12);
  }
}

TEST(Clusters, MesherGroupsASphereIntoClustersWithinTheirLimits)
{
  const RoomPolygons room = CurvedRoom(1, 1, 20000);
  SceneMesh plain, clustered;
  ASSERT_EQ(MeshByMaterial(room, 0.5, 0.1, 0, plain), "");
  ASSERT_EQ(MeshByMaterial(room, 0.5, 0.1, 30, clustered), "");
  const SceneGeometry gp(plain), gc(clustered);
  ASSERT_EQ(plain.NumberOfPolygons(), clustered.NumberOfPolygons());
  EXPECT_GT(gp.PatchElements.size(), 5 * gc.PatchElements.size());
  for (const std::vector<int>& patch : gc.PatchElements)
  {
    const NormalCone cone = ConeOf(gc, patch);
    EXPECT_LE(cone.Spread, 2 * 30 * Pi / 180 + 1e-9);
    for (int e : patch)
    {
      // Every element is within PatchSize / 2 of the cluster's seed: PatchSize across.
      EXPECT_TRUE(clustered.Reflectance[e] != kSphere || Norm(gc.Centroid[e] - gc.Centroid[patch[0]]) <= 0.5 + 1e-9);
    }
  }
  // The room's flat walls keep their patches: only small patches join.
  int flatPlain = 0, flatClustered = 0;
  for (const std::vector<int>& patch : gp.PatchElements)
  {
    flatPlain += plain.Reflectance[patch[0]] != kSphere ? 1 : 0;
  }
  for (const std::vector<int>& patch : gc.PatchElements)
  {
    flatClustered += clustered.Reflectance[patch[0]] != kSphere ? 1 : 0;
  }
  EXPECT_EQ(flatPlain, flatClustered);
  // The solver keeps each cluster whole: its elements see each other over the surface.
  const RadiositySolver solver(clustered);
  EXPECT_EQ(solver.SplitPatches(), 0);
}

TEST(Clusters, SphereRoomEqualsProgressiveRefinementOverEveryTriangle)
{
  const int lamps = 3;
  const RoomPolygons room = CurvedRoom(lamps, 1, 1200);
  SceneMesh plain, clustered;
  ASSERT_EQ(MeshByMaterial(room, 0.5, 0.25, 0, plain), "");
  ASSERT_EQ(MeshByMaterial(room, 0.5, 0.25, 30, clustered), "");
  const Solution reference = SolveRoom(plain, SolverMethod::ProgressiveRefinement, lamps);
  const Solution hierarchical = SolveRoom(clustered, SolverMethod::Hierarchical, lamps);
  const Solution progressive = SolveRoom(clustered, SolverMethod::ProgressiveRefinement, lamps);
  for (int m = 0; m < lamps; ++m)
  {
    const double h = MeanDifference(clustered, hierarchical, plain, reference, m);
    const double p = MeanDifference(clustered, progressive, plain, reference, m);
    std::printf("light %d: clusters, hierarchical %.3f %%, progressive %.3f %% from every triangle a patch\n", m,
      100 * h, 100 * p);
    EXPECT_LT(h, 0.01) << "light " << m;
    EXPECT_LT(p, 0.01) << "light " << m;
  }
}

namespace
{
/// The room with every quad split into an n x n grid of triangle pairs sharing points, as a
/// triangulating exporter writes it.
RoomPolygons Triangulated(const RoomPolygons& r, int n)
{
  RoomPolygons t;
  t.LightNames = r.LightNames;
  for (size_t c = 0; c + 1 < r.Offsets.size(); ++c)
  {
    const Vec3* q[4];
    for (int v = 0; v < 4; ++v)
    {
      q[v] = &r.Points[r.Connectivity[r.Offsets[c] + v]];
    }
    const int base = static_cast<int>(t.Points.size());
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const double u = double(i) / n, v = double(j) / n;
        t.Points.push_back(*q[0] * ((1 - u) * (1 - v)) + *q[1] * (u * (1 - v)) + *q[2] * (u * v) + *q[3] * ((1 - u) * v));
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int a = base + j * (n + 1) + i;
        for (const std::array<int, 3>& tri : { std::array<int, 3>{ a, a + 1, a + n + 2 }, std::array<int, 3>{ a, a + n + 2, a + n + 1 } })
        {
          t.Connectivity.insert(t.Connectivity.end(), tri.begin(), tri.end());
          t.Offsets.push_back(static_cast<int>(t.Connectivity.size()));
          t.Reflectance.push_back(r.Reflectance[c]);
          t.LightId.push_back(r.LightId[c]);
        }
      }
    }
  }
  return t;
}

/// Per material and light, the area mean of the radiosity over the scene's elements.
std::map<std::pair<std::array<double, 3>, int>, Vec3> MaterialMeans(const SceneMesh& mesh, const Solution& s)
{
  const SceneGeometry g(mesh);
  std::map<std::pair<std::array<double, 3>, int>, Vec3> sum;
  std::map<std::pair<std::array<double, 3>, int>, double> area;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const Vec3& rho = mesh.Reflectance[e];
    for (int m = 0; m < s.Solutions; ++m)
    {
      const auto key = std::make_pair(std::array<double, 3>{ rho.x, rho.y, rho.z }, m);
      sum[key] += s.Radiosity[static_cast<size_t>(e) * s.Solutions + m] * g.Area[e];
      area[key] += g.Area[e];
    }
  }
  for (auto& entry : sum)
  {
    entry.second = entry.second * (1.0 / area[entry.first]);
  }
  return sum;
}
} // namespace

TEST(Clusters, FinelyTriangulatedFlatSceneGivesTheSameRadiosity)
{
  const int lamps = 2;
  const RoomPolygons flat = CurvedRoom(lamps, 0, 0);
  SceneMesh plain, fine;
  ASSERT_EQ(MeshByMaterial(flat, 1.0, 0.25, 30, plain), "");
  ASSERT_EQ(MeshByMaterial(Triangulated(flat, 24), 1.0, 0.25, 30, fine), "");
  ASSERT_GT(fine.NumberOfPolygons(), 2 * plain.NumberOfPolygons());
  const Solution a = SolveRoom(plain, SolverMethod::Auto, lamps);
  const Solution b = SolveRoom(fine, SolverMethod::Auto, lamps);
  const auto meansA = MaterialMeans(plain, a), meansB = MaterialMeans(fine, b);
  ASSERT_EQ(meansA.size(), meansB.size());
  for (const auto& entry : meansA)
  {
    const Vec3& x = entry.second;
    const Vec3& y = meansB.at(entry.first);
    EXPECT_NEAR(x.x + x.y + x.z, y.x + y.y + y.z, 0.01 * (x.x + x.y + x.z)) << "light " << entry.first.second;
  }
}

TEST(Clusters, HundredThousandTriangleSphereRoomConvergesAndBalances)
{
  const int lamps = 3;
  SceneMesh mesh;
  ASSERT_EQ(MeshByMaterial(CurvedRoom(lamps, 1, 100000), 0.5, 0.1, 30, mesh), "");
  ASSERT_GT(mesh.NumberOfPolygons(), 50000);
  const RadiositySolver solver(mesh);
  SolverOptions o;
  o.ConvergenceThreshold = 1e-3;
  const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::LightTagged, o);
  const SolverStatistics& st = s.Statistics;
  EXPECT_EQ(st.SolverMethod, SolverMethod::Hierarchical);
  EXPECT_TRUE(st.Converged);
  EXPECT_GT(st.FaceClusters, 0);
  EXPECT_LT(solver.Geometry().PatchElements.size(), 1000u);
  // Emitted = absorbed + escaped + unshot, the absorbed part from the radiosity itself.
  const double absorbed = radiosity_test::AbsorbedPower(mesh, s);
  EXPECT_NEAR(st.EmittedPower, absorbed + st.EscapedPower + st.UnshotPower, 1e-6 * st.EmittedPower);
}

TEST(Clusters, SameResultOnAnyNumberOfThreadsAndLightTaggedEqualsCombined)
{
  const int lamps = 3;
  SceneMesh mesh;
  ASSERT_EQ(MeshByMaterial(CurvedRoom(lamps, 1, 4000), 0.5, 0.25, 30, mesh), "");
  const RadiositySolver solver(mesh);
  SolverOptions o = radiosity_test::Converged(1e-4);
  o.SolverMethod = SolverMethod::Hierarchical;
  o.Threads = 1;
  const Solution one = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::LightTagged, o);
  o.Threads = 3;
  const Solution three = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::LightTagged, o);
  ASSERT_EQ(one.Radiosity.size(), three.Radiosity.size());
  for (size_t i = 0; i < one.Radiosity.size(); ++i)
  {
    ASSERT_EQ(one.Radiosity[i].x, three.Radiosity[i].x) << i;
    ASSERT_EQ(one.Radiosity[i].z, three.Radiosity[i].z) << i;
  }
  // Light tagging: the sum of the k unit solutions is the solution of all lights at once.
  const Solution combined = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::StandardCombined, o);
  double diff = 0, sum = 0;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    Vec3 tagged;
    for (int m = 0; m < lamps; ++m)
    {
      tagged += one.Radiosity[static_cast<size_t>(e) * lamps + m];
    }
    const Vec3& all = combined.Radiosity[e];
    diff += std::fabs(tagged.x - all.x) + std::fabs(tagged.y - all.y) + std::fabs(tagged.z - all.z);
    sum += all.x + all.y + all.z;
  }
  EXPECT_LT(diff / sum, 0.002);
}
