// The ImGui side of Params: one widget per parameter, from its declaration.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/params.hpp"

namespace shadows {

bool Params::drawWidgets(const std::string& prefix) {
  return drawWidgets([&](const Param& p) { return p.name.rfind(prefix, 0) == 0; });
}

bool Params::drawWidgets(const std::function<bool(const Param&)>& which) {
  bool any = false;
  for (auto& p : params_) {
    if (!which(p)) continue;
    bool changed_now = false;
    if (p.hidden && p.hidden(*this)) continue;
    std::string idle = locked_ ? locked_(p) : std::string();
    if (idle.empty() && p.inactive) idle = p.inactive(*this);
    if (!idle.empty()) ImGui::BeginDisabled();
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp | (p.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
    switch (p.kind) {
      case ParamKind::Float: {
        float v = p.f();
        const float lo = static_cast<float>(p.min), hi = static_cast<float>(p.max);
        if (ImGui::SliderFloat(p.name.c_str(), &v, lo, hi, "%.4g", flags)) {
          setFloat(p, v);
          changed_now = true;
        }
        break;
      }
      case ParamKind::Int: {
        int v = p.i();
        const int lo = static_cast<int>(p.min), hi = static_cast<int>(p.max);
        if (ImGui::SliderInt(p.name.c_str(), &v, lo, hi, "%d", flags)) {
          setFloat(p, v);
          changed_now = true;
        }
        break;
      }
      case ParamKind::Bool: {
        bool v = p.b();
        if (ImGui::Checkbox(p.name.c_str(), &v)) {
          setFloat(p, v ? 1 : 0);
          changed_now = true;
        }
        break;
      }
      case ParamKind::Vec3: {
        glm::vec3 v = p.v();
        const float lo = static_cast<float>(p.min), hi = static_cast<float>(p.max);
        if (ImGui::DragFloat3(p.name.c_str(), &v.x, 0.05f, lo, hi, "%.2f", flags)) {
          setVec3(p, v);
          changed_now = true;
        }
        break;
      }
      case ParamKind::String: {
        // Applied on Enter only: a half-typed path is not a file yet.
        std::string& text = editing_.try_emplace(p.name, p.string_value).first->second;
        if (ImGui::InputText(p.name.c_str(), &text, ImGuiInputTextFlags_EnterReturnsTrue)) {
          const std::string refused = set(p.name, text);
          refused_[p.name] = refused;
          changed_now = refused.empty();
        }
        if (!ImGui::IsItemActive()) text = p.string_value;  // not typing: show what is in force
        break;
      }
      case ParamKind::Choice: {
        int v = p.i();
        if (ImGui::BeginCombo(p.name.c_str(), p.choice().c_str())) {
          for (int k = 0; k < static_cast<int>(p.choices.size()); ++k) {
            if (ImGui::Selectable(p.choices[static_cast<size_t>(k)].c_str(), k == v)) {
              setFloat(p, k);
              changed_now = true;
            }
          }
          ImGui::EndCombo();
        }
        break;
      }
    }
    p.widget_min = {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y};
    // The frame only, not the label drawn to its right.
    p.widget_max = {ImGui::GetItemRectMin().x + ImGui::CalcItemWidth(), ImGui::GetItemRectMax().y};
    if (!idle.empty()) ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip("%s%s%s", p.help.c_str(), idle.empty() ? "" : "\nnow: ", idle.c_str());
    }
    if (const auto it = refused_.find(p.name); it != refused_.end() && !it->second.empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", it->second.c_str());
    }
    any = any || changed_now;
  }
  return any;
}

}  // namespace shadows
