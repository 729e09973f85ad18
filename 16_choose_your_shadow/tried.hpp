// The settings a student has measured on one preset and light, each a point of cost (the
// frame's median time) against error (vis_mae against the truth), and the front through them:
// the panel draws it live, the current point ringed. bench_sweep draws the same front over a
// fixed sweep (docs/bench_16_choose_your_shadow.png); this is the student's own.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace shadows {

class Tried {
 public:
  struct Point {
    std::string where;  // the preset and the light: points on one plot share it
    std::string label;  // the settings, as the student would --set them
    size_t series = 0;  // the technique's index: its colour
    double ms = 0.0, error = 0.0;
  };
  // A measured setting: a new point, or the same settings measured again (the newer stands).
  void record(Point p) {
    const auto it = std::find_if(points_.begin(), points_.end(), [&](const Point& q) {
      return q.where == p.where && q.label == p.label;
    });
    if (it != points_.end()) {
      *it = std::move(p);
    } else {
      points_.push_back(std::move(p));
    }
  }
  // The points measured where `where` says, in the order first measured.
  std::vector<const Point*> at(const std::string& where) const {
    std::vector<const Point*> here;
    for (const Point& p : points_) {
      if (p.where == where) here.push_back(&p);
    }
    return here;
  }
  // Of `points`, those no other point beats in both cost and error (ties in both: the first),
  // cheapest first.
  static std::vector<const Point*> front(std::vector<const Point*> points) {
    std::stable_sort(points.begin(), points.end(), [](const Point* a, const Point* b) {
      return a->ms < b->ms || (a->ms == b->ms && a->error < b->error);
    });
    std::vector<const Point*> on;
    for (const Point* p : points) {
      if (on.empty() || p->error < on.back()->error) on.push_back(p);
    }
    return on;
  }
  void clear() { points_.clear(); }

 private:
  std::vector<Point> points_;
};

}  // namespace shadows
