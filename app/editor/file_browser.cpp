#include "app/editor/file_browser.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace amls::editor {

namespace {

std::string human_size(std::uintmax_t bytes) {
  char text[32];
  if (bytes < 1024)
    std::snprintf(text, sizeof text, "%ju B", bytes);
  else if (bytes < 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f KB", static_cast<double>(bytes) / 1024.0);
  else
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

}  // namespace

FileBrowser::FileBrowser(std::filesystem::path folder) { enter(folder); }

void FileBrowser::enter(const std::filesystem::path& folder) {
  listing_ = list_directory(folder);
  typed_ = listing_.path.string();
  selected_ = -1;
}

std::optional<std::string> FileBrowser::draw(bool& open, bool& estimate_normals) {
  if (!open) return std::nullopt;
  std::optional<std::string> chosen;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.5f * io.DisplaySize.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(34.0f * ImGui::GetFontSize(), 24.0f * ImGui::GetFontSize()), ImGuiCond_Appearing);
  if (!ImGui::Begin("Open a point set or scene", &open)) {
    ImGui::End();
    return chosen;
  }
  if (ImGui::Button("Up") && listing_.path.has_parent_path()) enter(listing_.path.parent_path());
  ImGui::SameLine();
  if (ImGui::Button("Refresh")) enter(listing_.path);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputText("##path", &typed_, ImGuiInputTextFlags_EnterReturnsTrue)) {
    std::error_code error;
    if (std::filesystem::is_directory(typed_, error))
      enter(typed_);
    else if (std::filesystem::is_regular_file(typed_, error))
      chosen = typed_;
  }
  if (!listing_.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.42f, 0.38f, 1.0f), "%s", listing_.error.c_str());
  const float footer = ImGui::GetFrameHeightWithSpacing();
  ImGui::BeginChild("entries", ImVec2(0.0f, -footer), true);
  std::optional<std::filesystem::path> next_folder;
  for (int i = 0; i < static_cast<int>(listing_.entries.size()); ++i) {
    const DirectoryEntry& entry = listing_.entries[static_cast<std::size_t>(i)];
    const std::string label = (entry.is_directory ? "[dir]  " : "       ") + entry.name;
    if (ImGui::Selectable(label.c_str(), selected_ == i, ImGuiSelectableFlags_AllowDoubleClick)) {
      selected_ = i;
      if (ImGui::IsMouseDoubleClicked(0)) {
        if (entry.is_directory)
          next_folder = listing_.path / entry.name;
        else
          chosen = (listing_.path / entry.name).string();
      }
    }
    if (!entry.is_directory) {
      ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 6.0f * ImGui::GetFontSize());
      ImGui::TextDisabled("%s", human_size(entry.size).c_str());
    }
  }
  ImGui::EndChild();
  const bool file_selected = selected_ >= 0 && !listing_.entries[static_cast<std::size_t>(selected_)].is_directory;
  ImGui::BeginDisabled(!file_selected);
  if (ImGui::Button("Open") && file_selected)
    chosen = (listing_.path / listing_.entries[static_cast<std::size_t>(selected_)].name).string();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) open = false;
  ImGui::SameLine();
  ImGui::TextDisabled(".ply .off .obj .stl .xyz .pwn .csv .txt (normals estimated where missing), .json scenes");
  ImGui::Checkbox("Estimate normals", &estimate_normals);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A point set's own normals set aside and estimated as for one without: for a scan whose "
                      "normals are unoriented (a face's all pointing inward). A scene's own 'normals' key decides for it.");
  ImGui::End();
  if (next_folder) enter(*next_folder);
  if (chosen) open = false;
  return chosen;
}

}  // namespace amls::editor
