// The split both volume trees make: the lower half of a range by key, ties by item, so the
// tree is the same whatever order the items came in.
#ifndef RadiosityCore_MedianSplit_h
#define RadiosityCore_MedianSplit_h

#include <algorithm>
#include <numeric>
#include <vector>

namespace radiosity
{

/// Reorders items[first, first + count) so that its first count / 2 hold the smallest
/// keys (key[i] belongs to items[first + i]); ties go by item.
inline void SplitAtMedian(std::vector<int>& items, int first, int count, const std::vector<long long>& key)
{
  std::vector<int> rank(count);
  std::iota(rank.begin(), rank.end(), 0);
  std::nth_element(rank.begin(), rank.begin() + count / 2, rank.end(), [&](int a, int b) {
    return key[a] < key[b] || (key[a] == key[b] && items[first + a] < items[first + b]);
  });
  std::vector<int> sorted(count);
  for (int i = 0; i < count; ++i)
  {
    sorted[i] = items[first + rank[i]];
  }
  std::copy(sorted.begin(), sorted.end(), items.begin() + first);
}

} // namespace radiosity

#endif
