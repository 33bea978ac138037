// amls-editor: drag handles and watch a point-set (AMLS) surface deform and resample live.
#include <exception>
#include <iostream>

#include "app/editor/editor_app.hpp"
#include "app/editor/editor_options.hpp"

int main(int argc, char** argv) {
  amls::editor::EditorOptions options;
  if (const std::optional<int> exit_code = amls::editor::parse_editor_options(argc, argv, options)) return *exit_code;
  try {
    amls::editor::EditorApp app(options);
    return app.run();
  } catch (const std::exception& e) {
    std::cerr << "amls-editor: error: " << e.what() << "\n";
    return 1;
  }
}
