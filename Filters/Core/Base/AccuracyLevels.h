// One accuracy setting for the whole pipeline: what each level sets. The mesher's Accuracy
// picks a level (and stamps it on its output, which the solver follows); relight.solve's
// `accuracy` reads the same table. Level 2 is the filters' own defaults.
#ifndef RadiosityCore_AccuracyLevels_h
#define RadiosityCore_AccuracyLevels_h

namespace radiosity
{

struct AccuracyLevel
{
  const char* Name;
  double ElementScale;      ///< times the element size given or suggested (at most the patch)
  double LampGrading;       ///< MesherOptions::LampGrading
  double ShadowGrading;     ///< MesherOptions::ShadowGrading
  int GatherRays;           ///< GatherSettings::Rays
  double ClusterSeparation; ///< ClusteredSettings::Separation
  int GatherSweeps;         ///< GatherSettings::Sweeps
};

constexpr int kAccuracyLevels = 5;

/// Level 0 (preview) to 4 (reference); measured on the FZK-Haus in docs/benchmarks.md.
inline const AccuracyLevel& AccuracyLevelOf(int level)
{
  static const AccuracyLevel levels[kAccuracyLevels] = {
    { "preview", 2.0, 0.3, 0.0, 64, 2.0, 1 },   // draft's elements, coarser grading, a light gather
    { "draft", 2.0, 0.2, 0.0, 256, 3.0, 1 },    // the default's gather on elements twice as large
    { "default", 1.0, 0.2, 0.0, 256, 3.0, 1 },  // the filters' defaults
    { "fine", 0.5, 0.2, 0.5, 256, 3.0, 3 },     // elements half as large, shadows' edges finer, three sweeps
    { "reference", 0.5, 0.15, 0.5, 1024, 4.0, 4 },
  };
  return levels[level < 0 ? 0 : level >= kAccuracyLevels ? kAccuracyLevels - 1 : level];
}

} // namespace radiosity

#endif
