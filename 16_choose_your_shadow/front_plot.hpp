// The panel's plot of cost against error (lesson 16): points in their technique's colour, log
// both ways, the front's steps through them, one point ringed, and a line at an error. The
// colours are bench_sweep's plot's (bench/plot.cpp), in the technique choice's order.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "tried.hpp"

namespace shadows {

inline constexpr ImU32 kTechniqueColours[] = {
    IM_COL32(224, 138, 0, 255),  IM_COL32(42, 157, 60, 255),  IM_COL32(142, 68, 173, 255),
    IM_COL32(22, 163, 184, 255), IM_COL32(214, 51, 108, 255), IM_COL32(122, 92, 46, 255),
    IM_COL32(90, 107, 140, 255), IM_COL32(181, 176, 0, 255),  IM_COL32(227, 119, 194, 255)};

inline ImU32 techniqueColour(size_t k) {
  return kTechniqueColours[k % std::size(kTechniqueColours)];
}

// `here` at the panel's cursor, `ring` ringed, a line at `error_now` where it is above 0; then
// the key: `keys[k]` in technique k's colour.
inline void drawFrontPlot(const std::vector<const Tried::Point*>& here, const Tried::Point* ring,
                          double error_now, const std::vector<std::string>& keys) {
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const Tried::Point* p : here) {
    x0 = std::min(x0, p->ms), x1 = std::max(x1, p->ms);
    y0 = std::min(y0, p->error), y1 = std::max(y1, p->error);
  }
  if (error_now > 0.0) y0 = std::min(y0, error_now), y1 = std::max(y1, error_now);
  const auto logOf = [](double v) { return std::log10(std::max(v, 1e-9)); };
  const double lx0 = logOf(x0) - 0.1, lx1 = logOf(x1) + 0.1;
  const double ly0 = logOf(y0) - 0.2, ly1 = logOf(y1) + 0.2;
  const float width = ImGui::GetContentRegionAvail().x, height = 0.6f * width;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRect(at, ImVec2(at.x + width, at.y + height), IM_COL32(120, 120, 120, 255));
  const auto y = [&](double error) {
    return at.y + height * static_cast<float>((ly1 - logOf(error)) / (ly1 - ly0));
  };
  const auto point = [&](const Tried::Point& p) {
    return ImVec2(at.x + width * static_cast<float>((logOf(p.ms) - lx0) / (lx1 - lx0)), y(p.error));
  };
  const std::vector<const Tried::Point*> on = Tried::front(here);
  for (size_t i = 1; i < on.size(); ++i) {  // steps: the least error for a time budget
    const ImVec2 a = point(*on[i - 1]), b = point(*on[i]);
    draw->AddLine(a, ImVec2(b.x, a.y), IM_COL32(31, 95, 168, 255), 2.0f);
    draw->AddLine(ImVec2(b.x, a.y), b, IM_COL32(31, 95, 168, 255), 2.0f);
  }
  for (const Tried::Point* p : here)
    draw->AddCircleFilled(point(*p), 4.0f, techniqueColour(p->series));
  if (ring != nullptr) draw->AddCircle(point(*ring), 8.0f, IM_COL32(208, 54, 44, 255), 0, 2.0f);
  if (error_now > 0.0) {
    draw->AddLine(ImVec2(at.x, y(error_now)), ImVec2(at.x + width, y(error_now)),
                  IM_COL32(208, 54, 44, 255), 1.5f);
  }
  ImGui::Dummy(ImVec2(width, height + 2.0f));
  for (size_t k = 0; k < keys.size(); ++k) {
    if (k % 5 != 0) ImGui::SameLine();
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(techniqueColour(k)), "%s", keys[k].c_str());
  }
}

}  // namespace shadows
