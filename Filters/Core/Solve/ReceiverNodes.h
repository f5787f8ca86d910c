// The parts through which a face cluster receives light: its cluster tree's nodes, so that
// a shooter can link to the whole cluster where it is far and to smaller parts where near.
#ifndef RadiosityCore_ReceiverNodes_h
#define RadiosityCore_ReceiverNodes_h

#include "Solve/ShooterFormFactors.h"

#include <vector>

namespace radiosity
{

/// Flat over all patches: every patch that is not flat gets its tree's nodes (or one node
/// of all its elements where it has no tree); flat patches get none.
struct ReceiverNodes
{
  std::vector<int> Root; ///< per patch, its first node (-1: a flat patch)
  std::vector<Vec3> Centre;
  std::vector<double> Radius;
  std::vector<NormalCone> Cone;
  std::vector<int> Left, Right; ///< children (-1: a leaf)
  std::vector<int> Patch;
  std::vector<int> ElementBegin, ElementEnd; ///< range in Elements
  std::vector<int> Elements;
  /// Sum of area x normal of each node's open (not sheltered) elements: the power it
  /// receives per unit shot radiosity through factor vector v is OpenArea . v.
  std::vector<Vec3> OpenArea;

  ReceiverNodes(const SceneGeometry& g, const ShooterFormFactors& factors)
    : Root(g.PatchElements.size(), -1)
  {
    for (size_t q = 0; q < g.PatchElements.size(); ++q)
    {
      if (factors.Planar(static_cast<int>(q)))
      {
        continue;
      }
      Root[q] = Count();
      const ClusterTree* tree = factors.Tree(static_cast<int>(q));
      const int first = static_cast<int>(Elements.size());
      if (!tree)
      {
        Elements.insert(Elements.end(), g.PatchElements[q].begin(), g.PatchElements[q].end());
        Add(g, static_cast<int>(q), factors.Centre(static_cast<int>(q)), factors.Radius(static_cast<int>(q)),
          factors.Cone(static_cast<int>(q)), -1, -1, first, static_cast<int>(g.PatchElements[q].size()));
        continue;
      }
      Elements.insert(Elements.end(), tree->Elements().begin(), tree->Elements().end());
      const int base = Count();
      for (const ClusterTree::Node& n : tree->AllNodes())
      {
        Add(g, static_cast<int>(q), n.Centre, n.Radius, n.Cone, n.Left < 0 ? -1 : base + n.Left,
          n.Right < 0 ? -1 : base + n.Right, first + n.First, n.Count);
      }
    }
  }

  int Count() const { return static_cast<int>(Centre.size()); }

private:
  /// A node of elements Elements[first, first + count).
  void Add(const SceneGeometry& g, int q, const Vec3& c, double r, const NormalCone& cone, int left, int right,
    int first, int count)
  {
    Centre.push_back(c);
    Radius.push_back(r);
    Cone.push_back(cone);
    Left.push_back(left);
    Right.push_back(right);
    Patch.push_back(q);
    ElementBegin.push_back(first);
    ElementEnd.push_back(first + count);
    Vec3 open;
    for (int i = first; i < first + count; ++i)
    {
      open += g.Sheltered[Elements[i]] ? Vec3() : g.Normal[Elements[i]] * g.Area[Elements[i]];
    }
    OpenArea.push_back(open);
  }
};

} // namespace radiosity

#endif
