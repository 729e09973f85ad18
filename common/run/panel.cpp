// The ImGui panel, the Runner's part: its sections (the lesson's idea first, then what every
// lesson shares, the cost, the error) and the exercise. The panel's texture in a window is
// RunnerWindow's (window.cpp).
#include "run/runner.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>

#include "gl/caps.hpp"
#include "truth/truth_job.hpp"

namespace shadows {

namespace {

// The lesson's title and seeds, then the two answers every lesson gives, where no scrolling
// hides them: how wrong, and (drawPanelWarnings) what it costs.
void drawPanelHeadline(const Lesson& lesson, const ErrorMeasure& errors, const RunOptions& options,
                       const SceneHost& host) {
  ImGui::TextWrapped("%s", lesson.title().c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", lesson.seeds().c_str());
  ImGui::PopStyleColor();
  const ErrorState& error = errors.truth().error();
  if (options.truth) {
    if (error.valid && error.metrics.counted_pixels == 0) {
      ImGui::TextWrapped("error: none counted (%s)", notCountedReason(error.metrics).c_str());
    } else if (error.valid) {
      ImGui::TextWrapped("error: false shadow %.2f%%, false lit %.2f%%",
                         error.metrics.false_shadow_pct, error.metrics.false_lit_pct);
    } else {
      ImGui::TextDisabled("error: measuring...");
    }
  }
  // A light map baking (lesson 15): the scene is drawn unbaked until it is in, and the truth
  // waits for it. Up here, where the sliders do not push it out of sight.
  if (const BakeState& bake = host.bakeState(); bake.stage == BakeState::Stage::kRunning) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("baking the light map: %.0f%% (drawn unbaked until then)",
                       100.0 * bake.progress);
    ImGui::PopStyleColor();
  }
}

void drawPanelCost(const Measure& measure, const RunnerWindow& window) {
  if (!ImGui::CollapsingHeader("Cost", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::TextWrapped("%s", window.costSummary().c_str());
  // One line per pass ever run, so widgets never jump around.
  const auto& work = measure.lastFrameWork();
  for (const auto& [pass, ms] : measure.medianPassMs()) {
    const auto it = work.find(pass);
    if (it == work.end()) {
      ImGui::Text("  %-8s skipped this frame", pass.c_str());
      continue;
    }
#ifndef __EMSCRIPTEN__
    ImGui::Text("  %-8s %6.2f ms %2lld draws", pass.c_str(), ms, it->second.draw_calls);
#else  // a pass's wall time in a page counts its calls, not its drawing: none is shown
    ImGui::Text("  %-8s %2lld draws", pass.c_str(), it->second.draw_calls);
#endif
    if (it->second.fragment_invocations) {
      ImGui::TextDisabled("           %lld fragments", *it->second.fragment_invocations);
    } else {
      ImGui::TextDisabled("           fragments %s", caps().unavailable().c_str());
    }
  }
  ImGui::TextWrapped("%s", window.counterSummary().c_str());
}

void drawPanelError(const ErrorMeasure& errors, const RunOptions& options) {
  if (!haveTruth() && ImGui::CollapsingHeader("Error", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::TextWrapped("%s", truthUnavailable().c_str());
  }
  if (!haveTruth() || !options.truth ||
      !ImGui::CollapsingHeader("Error", ImGuiTreeNodeFlags_DefaultOpen)) {
    return;
  }
  const TruthMeasure& truth = errors.truth();
  if (truth.running() && errors.progress() >= 0.0) {
    // A page's worker takes seconds; natively the truth is there before this shows.
    ImGui::TextDisabled("tracing the truth: %.0f%%", 100.0 * errors.progress());
  }
  if (!truth.error().valid) {
    if (truth.failed() && truth.key() == errors.key()) {
      ImGui::TextWrapped("the ray tracer failed: the browser's console says why");
    } else {
      ImGui::TextDisabled("not measured yet");
    }
    return;
  }
  const ErrorMetrics& e = truth.error().metrics;
  if (e.counted_pixels == 0) {
    ImGui::TextWrapped("No pixel counted: %s (is the eye inside an object?)",
                       notCountedReason(e).c_str());
  } else {
    ImGui::TextWrapped("false shadow %.3f%%  false lit %.3f%%", e.false_shadow_pct,
                       e.false_lit_pct);
    ImGui::TextWrapped("vis_mae %.4f  non-finite %lld  counted %lld%s", e.vis_mae,
                       e.nonfinite_pixels, e.counted_pixels,
                       truth.key() == errors.key() ? "" : "  (stale: updating)");
  }
  if (e.air.valid && !e.air.note.empty()) {
    ImGui::TextWrapped("air: 0 (%s)", e.air.note.c_str());
  } else if (e.air.valid && !e.air.rel_rmse_note.empty()) {
    ImGui::TextWrapped("air: mae %.4f  rel. RMSE: none (%s)", e.air.mae,
                       e.air.rel_rmse_note.c_str());
  } else if (e.air.valid) {
    ImGui::TextWrapped("air: mae %.4f  rel. RMSE %.1f%% (truth mean %.3f, noise %.4f)", e.air.mae,
                       100.0 * e.air.rel_rmse, e.air.truth_mean, e.air.truth_noise);
  }
}

}  // namespace

void Runner::drawPanel(Frame& frame) {
  beginPanel(frame);
  // Room for this lesson's longest label (lightmap.texels_per_unit was cut at 8.5 em), the
  // widgets keeping at least 45 % of the width.
  float label = ImGui::GetFontSize() * 8.5f;
  for (const Param& p : params_.all())
    label = std::max(label, ImGui::CalcTextSize(p.name.c_str()).x);
  label += ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::PushItemWidth(-std::min(label, 0.55f * ImGui::GetContentRegionAvail().x));
  drawPanelHeadline(*lesson_, errors_, options_, host_);
  drawExerciseChooser();
  if (const Exercise* ex = exercise_.chosen(); ex && !window_.exercise_strips) drawExercise(*ex);
  drawPanelWarnings();
  drawPanelSliders(frame);
  drawPanelCost(*measure_, window_);
  drawPanelError(errors_, options_);
  ImGui::PopItemWidth();
  ImGui::End();
  // The exercise around the picture, in windows of its own beside the panel's column.
  if (const Exercise* ex = exercise_.chosen(); ex && window_.exercise_strips) drawExercise(*ex);
}

void Runner::beginPanel(const Frame& frame) {
  const bool column = window_.column > 0;
  if (column) {
    // A window's panel is a column of its own right of the picture, never over it.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - RunnerWindow::kPanelColumn, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(RunnerWindow::kPanelColumn, display.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
  } else {
    // Over the picture (headless --panel, a window too narrow for a column): narrow, in the
    // top-left corner, folded whole on small pictures, where it would hide everything.
    const float width = std::min(300.0f, 0.45f * static_cast<float>(frame.width));
    // Placed once, then where the student drags it; placed again after a column (a window
    // made too narrow for one), whose place would be off the picture now.
    const ImGuiCond place = window_.was_column ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(ImVec2(6, 6), place);
    ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(frame.height) - 12), place);
    ImGui::SetNextWindowCollapsed(frame.width < 600, ImGuiCond_FirstUseEver);
  }
  window_.was_column = column;
  ImGui::Begin(
      name_.c_str(), nullptr,
      column ? ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse
             : 0);
}

// The lesson's exercises, one a choice: its goal, each figure now, met or not, on the last
// truth measured, under the error it is judged by.
void Runner::drawExerciseChooser() {
  const std::vector<Exercise> all = lesson_->exercises();
  if (all.empty() || !options_.truth) return;
  std::vector<std::string> names = {"no exercise: explore freely"};
  for (size_t i = 0; i < all.size(); ++i)
    names.push_back("exercise " + std::to_string(i + 1) + ": " + all[i].title);
  const int shown = std::clamp(exercise_.number(), 0, static_cast<int>(all.size()));
  // The whole width, its name in the choices: a title cut at the labels' column read
  // "1: Just enough map for th".
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::BeginCombo("##exercise", names[static_cast<size_t>(shown)].c_str())) {
    for (int k = 0; k < static_cast<int>(names.size()); ++k) {
      if (ImGui::Selectable(names[static_cast<size_t>(k)].c_str(), k == shown) && k != shown) {
        chooseExercise(k);
      }
    }
    ImGui::EndCombo();
  }
}

// Where no technique's answer is defined, the panel says so before its numbers; then the
// texels per pixel and the shadow's cost.
void Runner::drawPanelWarnings() {
  const ErrorState& error = errors_.truth().error();
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.2f, 1.0f));
  if (const std::string on = lightOnSurface(); !on.empty()) {
    ImGui::TextWrapped(
        "the light sits on the %s's surface: its faces there lie edge-on to it, "
        "and shadows near it are undefined",
        on.c_str());
  }
  if (error.valid && error.metrics.grazing_pixels > error.metrics.counted_pixels) {
    ImGui::TextWrapped("the light grazes most surfaces seen (N.L < %g): those are not counted",
                       static_cast<double>(kGrazingNdotL));
  }
  ImGui::PopStyleColor();
  if (const auto& texels = texels_.stats(); texels && texels->pixels == 0) {
    ImGui::TextWrapped("texels per pixel: none counted (no pixel seen lies in the map)");
  } else if (texels) {
    ImGui::TextWrapped("texels per pixel: median %.2f (least axis), %.1f%% under-sampled%s",
                       texels->min_axis.median, texels->undersampled_pct,
                       texels_.current() ? "" : " (stale)");
  }
  if (currentView() == views::kAliasing) TexelPass::drawLegend();
  if (const double overhead = baseline_.overhead(); overhead > 0.0) {
    ImGui::Text("cost: %.2fx the frame without shadow", overhead);
  }
}

// The view and scene, the buttons, then the lesson's own idea first and open; what every
// lesson shares folded below it.
void Runner::drawPanelSliders(Frame& frame) {
  const auto top = [](const Param& p) { return p.name == "view" || p.name == "scene"; };
  params_.drawWidgets(top);
  if (ImGui::Button("Screenshot (F12)")) window_.screenshot_requested = true;
  // An eye dragged out of the room or out of sight comes back (the C key too); not where an
  // exercise holds the camera.
  ImGui::SameLine();
  const Exercise* held = exercise_.chosen();
  ImGui::BeginDisabled(held != nullptr && !held->camera_free);
  if (ImGui::Button("Camera back (C)")) resetCamera();
  ImGui::EndDisabled();
  if (!headless_.screenshotSaid().empty()) {
    ImGui::SameLine();
    ImGui::TextWrapped("%s", headless_.screenshotSaid().c_str());
  }
  const auto lightOrCamera = [](const Param& p) {
    return p.name.rfind("light.", 0) == 0 || p.name.rfind("camera.", 0) == 0;
  };
  const auto section = [&](const char* title, bool open) {
    if (window_.open_sections.count(title) != 0 || window_.unfold.erase(title) != 0) {
      ImGui::SetNextItemOpen(true);
    }
    return ImGui::CollapsingHeader(title, open ? ImGuiTreeNodeFlags_DefaultOpen : 0);
  };
  if (section("Technique", true)) {
    params_.drawWidgets([&](const Param& p) { return !p.shared && !top(p); });
    // A lesson's own buttons set sliders an exercise may lock: off while one is chosen.
    if (exercise_.chosen()) ImGui::BeginDisabled();
    lesson_->panel(frame);
    if (exercise_.chosen()) ImGui::EndDisabled();
  }
  const auto mapSetting = [&](const Param& p) { return p.shared && !top(p) && !lightOrCamera(p); };
  const auto& all = params_.all();
  if (std::any_of(all.begin(), all.end(), mapSetting) && section("Shadow map", false)) {
    params_.drawWidgets(mapSetting);
  }
  if (section("Light and camera", false)) {
    params_.drawWidgets([&](const Param& p) { return p.shared && lightOrCamera(p); });
  }
}

void Runner::drawExercise(const Exercise& ex) {
  const bool strips = window_.exercise_strips;
  const auto wrapped = [](ImVec4 colour, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
  };
  const ImVec4 grey = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
  // Around the picture (its 640x480 in the bottom-left corner): the goal and the sliders in
  // the strip above it, the verdict beside it; what appears later (the figures, the hint)
  // below every control, so nothing moves under the cursor.
  const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar |
                                 ImGuiWindowFlags_NoSavedSettings;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float unit = window_.framebuffer.x > 0
                         ? display.x / static_cast<float>(window_.framebuffer.x)
                         : 1.0f;  // window units a framebuffer pixel
  const ImVec2 picture(kExerciseWidth * unit, kExerciseHeight * unit);
  const float beside = display.x - RunnerWindow::kPanelColumn;  // the picture's part's width
  if (strips) {
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(beside, display.y - picture.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("##exercise goal", nullptr, fixed);
  } else {
    ImGui::Separator();
  }
  ImGui::PushID("exercise");
  ImGui::TextWrapped("Exercise %d: %s", exercise_.number(), ex.title.c_str());
  ImGui::TextWrapped("%s", ex.goal.c_str());
  if (!strips && (options_.width != kExerciseWidth || options_.height != kExerciseHeight)) {
    ImGui::TextDisabled("(judged on a %dx%d picture, as --grade is; this one is %dx%d)",
                        kExerciseWidth, kExerciseHeight, options_.width, options_.height);
  }
  // The sliders the exercise lets the student move, right under its goal.
  if (strips) ImGui::PushItemWidth(std::min(420.0f, 0.5f * beside));
  params_.drawWidgets([&](const Param& p) { return p.name != "view" && allowedIn(ex, p.name); });
  if (strips) ImGui::PopItemWidth();
  wrapped(grey, std::string("the other sliders are locked") +
                    (ex.camera_free ? "; the camera may move" : "; the camera stays"));
  if (strips) {
    ImGui::PopID();
    ImGui::End();
    ImGui::SetNextWindowPos(ImVec2(picture.x, display.y - picture.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(beside - picture.x, picture.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("##exercise verdict", nullptr, fixed);
    ImGui::PushID("exercise");
  }
  const ImVec4 met_colour{0.4f, 1.0f, 0.4f, 1.0f}, unmet_colour{1.0f, 0.45f, 0.4f, 1.0f};
#ifndef __EMSCRIPTEN__
  // The submission: a file --grade reads back (--settings), named after the lesson.
  if (ImGui::Button("Save settings")) {
    const std::string file =
        name_ + "_exercise" + std::to_string(exercise_.number()) + "_settings.txt";
    const std::string problem = exercise_.save(file);
    window_.saved = problem.empty()
                        ? "saved " + file + ": hand it in, or grade it: " + name_ + " --grade " +
                              std::to_string(exercise_.number()) + " --settings " + file
                        : problem;
  }
  if (!window_.saved.empty()) ImGui::TextWrapped("%s", window_.saved.c_str());
#else
  // A page's submission is its address: these settings as a link.
  ImGui::TextWrapped("as a link: %s", exercise_.query().c_str());
#endif
  const Verdict& v = exercise_.verdict();
  if (!exercise_.judged()) {
    ImGui::TextDisabled("measuring...");
  } else {
    for (const FigureResult& f : v.figures) wrapped(f.met ? met_colour : unmet_colour, f.line());
    wrapped(
        v.met ? met_colour : unmet_colour,
        std::string(v.met ? "MET" : "not met yet") +
            (errors_.truth().key() == errors_.key() ? "" : " (measured before the last change)"));
    // After a minute without it, the hint: last, under everything.
    if (!v.met && !ex.hint.empty() && ImGui::GetTime() > 60.0) {
      ImGui::TextWrapped("hint: %s", ex.hint.c_str());
    }
  }
  ImGui::PopID();
  if (strips) ImGui::End();
}

}  // namespace shadows
