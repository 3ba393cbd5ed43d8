#include "core/mesh_simplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <queue>
#include <tuple>

namespace reflect {
namespace {

struct Vec3d {
  double x = 0.0, y = 0.0, z = 0.0;
};
Vec3d operator-(Vec3d a, Vec3d b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// The area-weighted sum of squared distances to a set of planes, as p^T A p + 2 b.p + c, and the
// sum of the weights (so that sum / weight is a mean squared distance).
struct Quadric {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0, bx = 0, by = 0, bz = 0, c = 0;
  double weight = 0;

  // The plane n.p + d = 0 (n of unit length), weighted by w.
  void addPlane(Vec3d n, double d, double w) {
    xx += w * n.x * n.x, xy += w * n.x * n.y, xz += w * n.x * n.z;
    yy += w * n.y * n.y, yz += w * n.y * n.z, zz += w * n.z * n.z;
    bx += w * n.x * d, by += w * n.y * d, bz += w * n.z * d;
    c += w * d * d, weight += w;
  }
  void add(const Quadric& q) {
    xx += q.xx, xy += q.xy, xz += q.xz, yy += q.yy, yz += q.yz, zz += q.zz;
    bx += q.bx, by += q.by, bz += q.bz, c += q.c, weight += q.weight;
  }
  double sumAt(Vec3d p) const {
    const double quadratic = xx * p.x * p.x + yy * p.y * p.y + zz * p.z * p.z +
                             2.0 * (xy * p.x * p.y + xz * p.x * p.z + yz * p.y * p.z);
    return quadratic + 2.0 * (bx * p.x + by * p.y + bz * p.z) + c;
  }
};

// Moving vertex `from` onto vertex `to`, at `cost`; stale once either vertex's stamp moves on.
struct Collapse {
  double cost;
  uint32_t from, to, fromStamp, toStamp;
};
// The heap's order: cheapest first, ties by the vertices' numbers and stamps (a total order, so
// the collapses come out in the same sequence whatever the standard library's heap does).
struct CostlierFirst {
  bool operator()(const Collapse& a, const Collapse& b) const {
    return std::tie(a.cost, a.from, a.to, a.fromStamp, a.toStamp) >
           std::tie(b.cost, b.from, b.to, b.fromStamp, b.toStamp);
  }
};

class Simplifier {
 public:
  Simplifier(const std::vector<Vertex>& vertices, std::span<const uint32_t> indices)
      : vertices_(vertices), indices_(indices) {
    weld();
    normalisePositions();
    makeTriangles();
    lockBorders();
    for (uint32_t t = 0; t < corners_.size(); ++t) {
      if (!alive_[t]) continue;
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = corners_[t][k], b = corners_[t][(k + 1) % 3];
        if (a < b) pushEdge(a, b), pushEdge(b, a);  // each interior edge once, from one side
      }
    }
  }

  void run(size_t targetTriangles, double maxError) {
    const double limit = maxError * maxError;  // costs are squared distances
    while (liveTriangles_ > targetTriangles && !queue_.empty()) {
      const Collapse next = queue_.top();
      queue_.pop();
      if (next.fromStamp != stamp_[next.from] || next.toStamp != stamp_[next.to]) continue;
      if (next.cost > limit) break;  // every later collapse costs at least as much
      if (!linkHolds(next.from, next.to) || flips(next.from, next.to)) continue;
      collapse(next.from, next.to);
    }
  }

  std::vector<uint32_t> result() const {
    std::vector<uint32_t> out;
    out.reserve(liveTriangles_ * 3);
    for (uint32_t t = 0; t < corners_.size(); ++t) {
      if (!alive_[t]) continue;
      for (int k = 0; k < 3; ++k) out.push_back(cornerVertex(indices_[t * 3 + k], corners_[t][k]));
    }
    return out;
  }

 private:
  // Vertices at one position become one: weld_[v] is the lowest-numbered vertex there. The ids
  // sorted by position then number (byPosition_) hold each position's vertices together.
  void weld() {
    const size_t n = vertices_.size();
    byPosition_.resize(n);
    std::iota(byPosition_.begin(), byPosition_.end(), 0u);
    std::sort(byPosition_.begin(), byPosition_.end(), [&](uint32_t a, uint32_t b) {
      const glm::vec3 &p = vertices_[a].position, &q = vertices_[b].position;
      return std::tie(p.x, p.y, p.z, a) < std::tie(q.x, q.y, q.z, b);
    });
    weld_.resize(n);
    groupBegin_.assign(n, 0);
    groupEnd_.assign(n, 0);
    for (size_t i = 0; i < n;) {
      size_t end = i + 1;
      const glm::vec3& p = vertices_[byPosition_[i]].position;
      while (end < n && vertices_[byPosition_[end]].position == p) ++end;
      const uint32_t first = byPosition_[i];
      for (size_t j = i; j < end; ++j) weld_[byPosition_[j]] = first;
      groupBegin_[first] = static_cast<uint32_t>(i);
      groupEnd_[first] = static_cast<uint32_t>(end);
      i = end;
    }
  }

  // Positions relative to the used vertices' bounds, in units of their largest side: costs are
  // then fractions of the extent, as the target error is.
  void normalisePositions() {
    glm::vec3 low(0.0f), high(0.0f);
    bool any = false;
    for (uint32_t index : indices_) {
      if (index >= vertices_.size()) continue;
      const glm::vec3& p = vertices_[index].position;
      low = any ? glm::min(low, p) : p;
      high = any ? glm::max(high, p) : p;
      any = true;
    }
    const glm::vec3 size = high - low;
    const double extent = std::max({double{size.x}, double{size.y}, double{size.z}});
    const double scale = extent > 0.0 ? 1.0 / extent : 1.0;
    position_.resize(vertices_.size());
    for (size_t v = 0; v < vertices_.size(); ++v) {
      const glm::vec3& p = vertices_[v].position;
      position_[v] = {(double{p.x} - low.x) * scale, (double{p.y} - low.y) * scale,
                      (double{p.z} - low.z) * scale};
    }
  }

  // Each triangle over welded vertices, and each vertex's quadric from the planes around it.
  void makeTriangles() {
    const size_t triangles = indices_.size() / 3;
    corners_.resize(triangles);
    alive_.assign(triangles, 0);
    around_.resize(vertices_.size());
    quadric_.resize(vertices_.size());
    stamp_.assign(vertices_.size(), 0);
    locked_.assign(vertices_.size(), 0);
    for (uint32_t t = 0; t < triangles; ++t) {
      std::array<uint32_t, 3>& c = corners_[t];
      bool inRange = true;
      for (int k = 0; k < 3; ++k) {
        inRange = inRange && indices_[t * 3 + k] < vertices_.size();
        c[k] = inRange ? weld_[indices_[t * 3 + k]] : 0;
      }
      if (!inRange || c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
      alive_[t] = 1;
      ++liveTriangles_;
      const Vec3d normal =
          cross(position_[c[1]] - position_[c[0]], position_[c[2]] - position_[c[0]]);
      const double length = std::sqrt(dot(normal, normal));
      for (int k = 0; k < 3; ++k) {
        around_[c[k]].push_back(t);
        if (length > 0.0) {
          const Vec3d unit{normal.x / length, normal.y / length, normal.z / length};
          quadric_[c[k]].addPlane(unit, -dot(unit, position_[c[0]]), length * 0.5);
        }
      }
    }
  }

  // An edge with other than two triangles is an open border or non-manifold: its ends never move.
  void lockBorders() {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (uint32_t t = 0; t < corners_.size(); ++t) {
      if (!alive_[t]) continue;
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = corners_[t][k], b = corners_[t][(k + 1) % 3];
        edges.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
      size_t end = i + 1;
      while (end < edges.size() && edges[end] == edges[i]) ++end;
      if (end - i != 2) locked_[edges[i].first] = locked_[edges[i].second] = 1;
      i = end;
    }
  }

  void pushEdge(uint32_t from, uint32_t to) {
    if (locked_[from]) return;
    const Quadric &a = quadric_[from], &b = quadric_[to];
    const double weight = a.weight + b.weight;
    const double sum = a.sumAt(position_[to]) + b.sumAt(position_[to]);
    const double cost = weight > 0.0 ? std::max(sum, 0.0) / weight : 0.0;
    queue_.push({cost, from, to, stamp_[from], stamp_[to]});
  }

  // The live vertices that share a live triangle with `v`, in increasing order.
  std::vector<uint32_t> neighbours(uint32_t v) const {
    std::vector<uint32_t> out;
    for (uint32_t t : around_[v]) {
      if (!alive_[t]) continue;
      for (uint32_t c : corners_[t]) {
        if (c != v) out.push_back(c);
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // The link condition for an interior edge: its ends share exactly the two vertices opposite it,
  // so the collapse neither pinches the surface nor folds two triangles onto each other.
  bool linkHolds(uint32_t a, uint32_t b) const {
    const std::vector<uint32_t> na = neighbours(a), nb = neighbours(b);
    if (!std::binary_search(na.begin(), na.end(), b)) return false;
    std::vector<uint32_t> shared;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(shared));
    return shared.size() == 2;
  }

  // Whether moving `a` onto `b` turns a surviving triangle around `a` over (or to nothing).
  bool flips(uint32_t a, uint32_t b) const {
    for (uint32_t t : around_[a]) {
      if (!alive_[t]) continue;
      const std::array<uint32_t, 3>& c = corners_[t];
      if (c[0] == b || c[1] == b || c[2] == b) continue;  // removed by the collapse
      std::array<Vec3d, 3> before{position_[c[0]], position_[c[1]], position_[c[2]]};
      std::array<Vec3d, 3> after = before;
      for (int k = 0; k < 3; ++k) {
        if (c[k] == a) after[k] = position_[b];
      }
      const Vec3d n0 = cross(before[1] - before[0], before[2] - before[0]);
      const Vec3d n1 = cross(after[1] - after[0], after[2] - after[0]);
      const double l1 = dot(n1, n1);
      if (l1 == 0.0) return true;
      // A turn of more than about 87 degrees counts as a flip: such a triangle is a sliver.
      if (dot(n0, n1) <= 0.05 * std::sqrt(dot(n0, n0) * l1)) return true;
    }
    return false;
  }

  void collapse(uint32_t a, uint32_t b) {
    for (uint32_t t : around_[a]) {
      if (!alive_[t]) continue;
      std::array<uint32_t, 3>& c = corners_[t];
      if (c[0] == b || c[1] == b || c[2] == b) {
        alive_[t] = 0;
        --liveTriangles_;
        continue;
      }
      for (uint32_t& corner : c) {
        if (corner == a) corner = b;
      }
      around_[b].push_back(t);
    }
    around_[a] = {};
    locked_[a] = 1;  // gone: no edge starts from it again
    ++stamp_[a];
    quadric_[b].add(quadric_[a]);
    ++stamp_[b];
    std::vector<uint32_t>& list = around_[b];
    list.erase(std::remove_if(list.begin(), list.end(), [&](uint32_t t) { return !alive_[t]; }),
               list.end());
    for (uint32_t n : neighbours(b)) pushEdge(b, n), pushEdge(n, b);
  }

  // The vertex a corner ends at: its own where its position stayed, else of the vertices at its
  // new position the one whose normal is nearest its own (the lowest-numbered on a tie).
  uint32_t cornerVertex(uint32_t original, uint32_t welded) const {
    if (weld_[original] == welded) return original;
    const glm::vec3& normal = vertices_[original].normal;
    uint32_t best = welded;
    float bestDot = -2.0f;
    for (uint32_t i = groupBegin_[welded]; i < groupEnd_[welded]; ++i) {
      const uint32_t candidate = byPosition_[i];
      const float d = glm::dot(normal, vertices_[candidate].normal);
      if (d > bestDot) best = candidate, bestDot = d;
    }
    return best;
  }

  const std::vector<Vertex>& vertices_;
  std::span<const uint32_t> indices_;
  std::vector<uint32_t> byPosition_, weld_, groupBegin_, groupEnd_;
  std::vector<Vec3d> position_;
  std::vector<std::array<uint32_t, 3>> corners_;
  std::vector<uint8_t> alive_, locked_;
  std::vector<std::vector<uint32_t>> around_;
  std::vector<Quadric> quadric_;
  std::vector<uint32_t> stamp_;
  std::priority_queue<Collapse, std::vector<Collapse>, CostlierFirst> queue_;
  size_t liveTriangles_ = 0;
};

}  // namespace

std::vector<uint32_t> simplifyMesh(const std::vector<Vertex>& vertices,
                                   std::span<const uint32_t> indices, size_t targetIndexCount,
                                   float targetError) {
  Simplifier simplifier(vertices, indices);
  simplifier.run(targetIndexCount / 3, double{targetError});
  return simplifier.result();
}

}  // namespace reflect
