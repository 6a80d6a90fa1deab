#pragma once
// Labels placed where they cover nothing: the sphere panel's (chart poles, seams, loci); any panel may use it.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "render/panels.hpp"

namespace sl {

// The labels and marks of the panel, as boxes, for a label to find a place that covers none of them.
struct Box {
  float x0, y0, x1, y1;
};

inline float overlapArea(const Box& a, const Box& b) {
  const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0;
}

// Candidate places around an anchor: 8 directions, near and then at growing distances (with a leader line). A
// candidate that overlaps anything already placed (a ball, a label) or leaves the area is refused; of the others the
// one covering the fewest path points wins, nearer first on a tie. Nothing outside the area: a label never reaches
// the title band, a neighbouring panel or the colour bar's strip. No place at all: no label.
class LabelPlacer {
 public:
  explicit LabelPlacer(const PixelRect& area) : area_(area) {}
  void avoid(const Box& box) { taken_.push_back(box); }
  void avoidPoint(P2 p) { points_.push_back(p); }
  // A ball: its square is avoided as a box; its disc is where a leader line may not run (over the ball).
  void avoidBall(P2 at, float radius) {
    avoid({at.x - radius, at.y - radius, at.x + radius, at.y + radius});
    balls_.push_back({at, radius});
  }
  bool onBall(P2 p) const {
    return std::any_of(balls_.begin(), balls_.end(), [&](const auto& ball) {
      return std::hypot(p.x - ball.first.x, p.y - ball.first.y) < ball.second;
    });
  }
  // Where a leader line from `anchor` to `to` starts: the anchor, or for an anchor under a ball (a pole or a seam a
  // state sits on) the edge of the ball, of the balls spread over it one after another: a leader never strikes
  // through the ball over its anchor.
  P2 leaderStart(P2 anchor, P2 to) const {
    const float dx = to.x - anchor.x, dy = to.y - anchor.y, length = std::hypot(dx, dy);
    if (length <= 0) return anchor;
    float from = 0;  // along the line, as a fraction of its length
    for (std::size_t pass = 0; pass < balls_.size(); ++pass) {
      bool moved = false;
      for (const auto& [at, radius] : balls_) {
        // The line's parameters s where |anchor + s (to - anchor) - at| = radius: entry and exit.
        const float ox = anchor.x - at.x, oy = anchor.y - at.y;
        const float b = (ox * dx + oy * dy) / (length * length);
        const float c = (ox * ox + oy * oy - radius * radius) / (length * length);
        if (b * b - c <= 0) continue;
        const float exit = -b + std::sqrt(b * b - c), entry = -b - std::sqrt(b * b - c);
        if (entry <= from && exit > from) {
          from = std::min(exit, 1.0f);
          moved = true;
        }
      }
      if (!moved) break;
    }
    return {anchor.x + from * dx, anchor.y + from * dy};
  }
  // Whether the leader from `anchor` to the nearest point of `box` runs over a ball (past those over the anchor,
  // which it starts beyond): a leader strikes through no ball.
  bool leaderCrossesABall(P2 anchor, const Box& box) const {
    const P2 to{std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1)};
    const P2 from = leaderStart(anchor, to);
    const float dx = to.x - from.x, dy = to.y - from.y, length2 = dx * dx + dy * dy;
    return std::any_of(balls_.begin(), balls_.end(), [&](const auto& ball) {
      const auto& [at, radius] = ball;
      const float s =
          length2 > 0 ? std::clamp(((at.x - from.x) * dx + (at.y - from.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
      return std::hypot(from.x + s * dx - at.x, from.y + s * dy - at.y) < 0.99f * radius;
    });
  }
  void recordLeader(P2 from, P2 to) { leaders_.push_back({from, to}); }
  const std::vector<std::array<P2, 2>>& leaders() const { return leaders_; }
  // The box of a label of `width` x `height` placed near `anchor`, and whether it is far enough to need a leader.
  std::optional<std::pair<Box, bool>> place(P2 anchor, float width, float height, float clearance) {
    std::optional<std::pair<Box, bool>> best;
    float bestScore = 0;
    for (const float reach : {1.0f, 2.5f, 4.5f, 7.0f}) {
      for (int k = 0; k < 8; ++k) {
        const float a = 0.7853982f * float(k) - 0.7853982f;  // up-right first, then clockwise
        const float dx = std::cos(a), dy = std::sin(a);
        const float r = reach * clearance;
        // The box touches the circle of radius r about the anchor on the side facing it.
        const float cx = anchor.x + dx * (r + 0.5f * width * std::abs(dx));
        const float cy = anchor.y + dy * (r + 0.5f * height * std::abs(dy));
        const Box box{cx - 0.5f * width, cy - 0.5f * height, cx + 0.5f * width, cy + 0.5f * height};
        // A wide box on a diagonal reaches back over its anchor and the mark drawn there (a pole's ring): refused.
        const float nearX = std::clamp(anchor.x, box.x0, box.x1) - anchor.x,
                    nearY = std::clamp(anchor.y, box.y0, box.y1) - anchor.y;
        if (std::hypot(nearX, nearY) < 0.6f * clearance) continue;
        if (box.x0 < area_.x || box.y0 < area_.y || box.x1 > area_.x + area_.width || box.y1 > area_.y + area_.height)
          continue;
        if (std::any_of(taken_.begin(), taken_.end(), [&](const Box& t) { return overlapArea(box, t) > 0; })) continue;
        if (reach > 1 && leaderCrossesABall(anchor, box)) continue;
        float score = reach;  // nearer wins a tie
        for (const P2& p : points_)
          if (p.x > box.x0 && p.x < box.x1 && p.y > box.y0 && p.y < box.y1) score += 10;
        if (!best || score < bestScore) {
          best = std::make_pair(box, reach > 1);
          bestScore = score;
        }
      }
    }
    if (best) taken_.push_back(best->first);
    return best;
  }

 private:
  PixelRect area_;
  std::vector<Box> taken_;
  std::vector<P2> points_;
  std::vector<std::pair<P2, float>> balls_;
  std::vector<std::array<P2, 2>> leaders_;
};

}  // namespace sl
