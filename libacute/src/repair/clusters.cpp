#include <acute/repair/clusters.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace acute {

std::vector<Cluster> find_clusters(const Mesh& mesh, const AngleBounds& bounds, const std::vector<bool>& forced) {
  std::vector<FaceHandle> bad;
  for (auto fh : mesh.faces())
    if (is_bad_triangle(mesh, fh, bounds, forced)) bad.push_back(fh);
  // Union-find over bad faces that share a vertex.
  std::vector<int> parent(bad.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<int, int> owner;  // vertex idx -> a bad face index touching it
  for (int i = 0; i < static_cast<int>(bad.size()); ++i)
    for (auto vh : mesh.fv_range(bad[i])) {
      auto [it, inserted] = owner.emplace(vh.idx(), i);
      if (!inserted) parent[find(i)] = find(it->second);
    }
  std::vector<int> slot(bad.size(), -1);
  std::vector<Cluster> clusters;
  for (int i = 0; i < static_cast<int>(bad.size()); ++i) {
    const int r = find(i);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(clusters.size());
      clusters.emplace_back();
    }
    Cluster& c = clusters[slot[r]];
    c.bad.push_back(bad[i]);
    bool exempt = false;
    for (auto vh : mesh.fv_range(bad[i])) {
      c.vertices.push_back(vh);
      exempt = exempt || forced[static_cast<std::size_t>(vh.idx())];
    }
    c.worst_margin = std::min(c.worst_margin, triangle_margin(mesh, bad[i], bounds, exempt));
  }
  for (auto& c : clusters) {
    std::sort(c.vertices.begin(), c.vertices.end());
    c.vertices.erase(std::unique(c.vertices.begin(), c.vertices.end()), c.vertices.end());
  }
  std::stable_sort(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) { return a.worst_margin < b.worst_margin; });
  return clusters;
}

}  // namespace acute
