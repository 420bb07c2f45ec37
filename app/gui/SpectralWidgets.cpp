#include "gui/SpectralWidgets.hpp"

#include "gui/PanelWidgets.hpp"
#include "spectrum/Colour.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace dropscope::gui {

namespace {

constexpr int kBarSteps = 80;        // colour steps across a wavelength bar: 5 nm over the visible
constexpr int kPreviewColumns = 60;  // columns of a spectrum's preview
constexpr float kRemoveWidth = 22.0f;

ImU32 colourOf(double wavelengthNm) {
    const Rgb rgb = displayColourOfWavelength(wavelengthNm);
    return ImGui::ColorConvertFloat4ToU32(
        ImVec4(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]), 1.0f));
}

}  // namespace

bool editRows(const char* label, std::vector<std::array<double, 2>>& rows, int columns, std::array<double, 2> newRow,
              double step, const ItemProbe& probe) {
    bool changed = false;
    ImGui::PushID(label);
    std::ptrdiff_t removed = -1;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - kRemoveWidth - ImGui::GetStyle().ItemSpacing.x);
        changed |= ImGui::InputScalarN("##row", ImGuiDataType_Double, rows[i].data(), columns, nullptr, nullptr, "%.6g",
                                       ImGuiInputTextFlags_EnterReturnsTrue);
        reportItemRect(probe, std::string(label) + " " + std::to_string(i));
        ImGui::SameLine();
        if (ImGui::Button("x", ImVec2(kRemoveWidth, 0.0f))) removed = static_cast<std::ptrdiff_t>(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("remove this row");
        ImGui::PopID();
    }
    if (removed >= 0) {
        rows.erase(rows.begin() + removed);
        changed = true;
    }
    if (ImGui::SmallButton("Add row")) {
        if (!rows.empty() && step > 0.0) newRow = {rows.back()[0] + step, rows.back()[1]};
        rows.push_back(newRow);
        changed = true;
    }
    reportItemRect(probe, std::string(label) + " add");
    ImGui::PopID();
    return changed;
}

void wavelengthBar(double loNm, double hiNm, float width, float height) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float step = width / kBarSteps;
    for (int k = 0; k < kBarSteps; ++k) {
        const double nm = loNm + (hiNm - loNm) * (k + 0.5) / kBarSteps;
        const ImVec2 from(at.x + step * static_cast<float>(k), at.y);
        draw->AddRectFilled(from, ImVec2(from.x + step + 0.5f, at.y + height), colourOf(nm));
    }
    ImGui::Dummy(ImVec2(width, height));
}

void spectrumPreview(const Spectrum& spectrum, float width, float height) {
    const auto [first, last] = spectrum.rangeNm();
    const double lo = std::min(kVisibleRangeNm[0], first);
    const double hi = std::max(kVisibleRangeNm[1], last);
    std::array<double, kPreviewColumns> shares{};
    double previous = spectrum.cdf(lo - 1e-9);  // a line at lo counts in the first column
    for (int k = 0; k < kPreviewColumns; ++k) {
        const double cumulative = spectrum.cdf(lo + (hi - lo) * (k + 1) / kPreviewColumns);
        shares[static_cast<std::size_t>(k)] = cumulative - previous;
        previous = cumulative;
    }
    const double tallest = std::max(*std::max_element(shares.begin(), shares.end()), 1e-300);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + width, at.y + height), ImGui::GetColorU32(ImGuiCol_FrameBg));
    const float step = width / kPreviewColumns;
    for (int k = 0; k < kPreviewColumns; ++k) {
        const double share = shares[static_cast<std::size_t>(k)];
        if (!(share > 0.0)) continue;
        const auto top = static_cast<float>(height * (1.0 - share / tallest));
        const double nm = lo + (hi - lo) * (k + 0.5) / kPreviewColumns;
        const ImVec2 from(at.x + step * static_cast<float>(k), at.y + top);
        draw->AddRectFilled(from, ImVec2(from.x + step + 0.5f, at.y + height), colourOf(nm));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::SameLine();
    if (first == last) {
        ImGui::TextDisabled("one line, %.6g nm", first);
    } else {
        ImGui::TextDisabled("%.6g-%.6g nm", first, last);
    }
}

}  // namespace dropscope::gui
