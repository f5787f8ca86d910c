// ./relight bench polygons: solve time, memory and shots of a room with tessellated
// spheres as their triangles grow, face clusters on and off. One scene a run (the driver,
// polygons_bench.py, sweeps sizes and draws the figure); prints one CSV row.
#include "BenchClock.h"
#include "BenchMethods.h"
#include "CurvedRoom.h"
#include "ProbeReference.h"
#include "Solve/LightSolutions.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

using namespace radiosity;
using namespace radiosity_bench;
using namespace radiosity_scenes;

int main(int argc, char** argv)
{
  int triangles = 20000, spheres = 1, lamps = 3;
  double patch = 0.5, element = 0.1, cone = 30, budget = 0, threshold = 1e-3;
  SolverMethod method = SolverMethod::Auto;
  std::vector<std::string> models; // OFF meshes to stand in the room beside the spheres
  bool compare = false;             // also solve by progressive refinement and print the difference
  std::string exportPath;           // write the room and probe points for Mitsuba, and stop
  std::string referencePath;        // Mitsuba's radiosity at the probes: print the error
  bool combined = false;            // one solution for all lights (k = 1), not one per light
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string flag = argv[i];
    const char* value = argv[i + 1];
    if (flag == "--triangles") triangles = std::atoi(value);
    else if (flag == "--spheres") spheres = std::atoi(value);
    else if (flag == "--lamps") lamps = std::atoi(value);
    else if (flag == "--patch") patch = std::atof(value);
    else if (flag == "--element") element = std::atof(value);
    else if (flag == "--cluster-angle") cone = std::atof(value);
    else if (flag == "--time-budget") budget = std::atof(value);
    else if (flag == "--threshold") threshold = std::atof(value);
    else if (flag == "--off") models.push_back(value);
    else if (flag == "--compare") compare = std::strcmp(value, "progressive") == 0;
    else if (flag == "--export") exportPath = value;
    else if (flag == "--combined") combined = std::atoi(value) != 0;
    else if (flag == "--reference") referencePath = value;
    else if (flag == "--method")
      method = MethodNamed(value);
  }
  const double t0 = Now();
  SceneMesh mesh;
  RoomPolygons room = CurvedRoom(lamps, triangles > 0 ? spheres : 0, triangles);
  for (size_t i = 0; i < models.size(); ++i)
  {
    if (!AddOffMesh(room, models[i], 1.2, 1.8 + 2.4 * (i % 2), 2.5, { 0.65, 0.6, 0.55 }))
    {
      std::fprintf(stderr, "cannot read %s as OFF\n", models[i].c_str());
      return 1;
    }
  }
  const std::string error = MeshByMaterial(room, patch, element, cone, mesh);
  if (!error.empty())
  {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const double t1 = Now();
  const RadiositySolver solver(mesh);
  const double t2 = Now();
  const Probes probes(3000);
  if (!exportPath.empty())
  {
    ExportRoom(room, solver, mesh, probes, exportPath);
    return 0;
  }
  SolverOptions options;
  options.SolverMethod = method;
  options.TimeBudget = budget;
  options.ConvergenceThreshold = threshold;
  const SolutionMode mode = combined ? SolutionMode::StandardCombined : SolutionMode::LightTagged;
  const Solution s = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, mode, options);
  const double t3 = Now();
  const SolverStatistics& st = s.Statistics;
  const int inputTriangles = static_cast<int>(room.Offsets.size()) - 1 - 6 - lamps;
  double probeError = std::nan(""), worst = std::nan("");
  if (!referencePath.empty())
  {
    probeError = MeanError(Sample(solver, mesh, s, probes), ReadReference(referencePath, probes.Origin.size(), lamps), lamps, &worst);
  }
  std::printf("triangles,elements,patches,lights,cluster_angle,method,shots,converged,rays,patch_links,element_links,link_mb,mesh_s,prepare_s,solve_s,total_s,peak_mb,error_pct,worst_light_pct,cluster_links\n");
  std::printf("%d,%d,%zu,%d,%g,%s,%d,%d,%lld,%lld,%lld,%.1f,%.2f,%.2f,%.2f,%.2f,%.0f,%.2f,%.2f,%lld\n", inputTriangles, mesh.NumberOfPolygons(),
    solver.Geometry().PatchElements.size(), lamps, cone, ShortMethodName(st.SolverMethod).c_str(), st.Shots, st.Converged ? 1 : 0,
    st.RayCount, st.PatchLinks, st.ElementLinks, st.LinkBytes / 1e6, t1 - t0, t2 - t1, t3 - t2, t3 - t0, PeakMemoryMB(),
    100 * probeError, 100 * worst, st.VolumeLinks);
  if (compare)
  {
    options.SolverMethod = SolverMethod::ProgressiveRefinement;
    const Solution p = SolveLights(solver, mesh, LightGrouping::OnePerLight(lamps), {}, SolutionMode::LightTagged, options);
    const SceneGeometry& g = solver.Geometry();
    for (int m = 0; m < lamps; ++m)
    {
      double diff = 0, sum = 0;
      for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
      {
        const Vec3& a = s.Radiosity[static_cast<size_t>(e) * lamps + m];
        const Vec3& b = p.Radiosity[static_cast<size_t>(e) * lamps + m];
        diff += (std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z)) * g.Area[e];
        sum += (b.x + b.y + b.z) * g.Area[e];
      }
      std::printf("light %d: %s differs from progressive refinement by %.3f %% (mean, area-weighted)\n", m,
        ShortMethodName(st.SolverMethod).c_str(), 100 * diff / sum);
    }
  }
  return 0;
}
