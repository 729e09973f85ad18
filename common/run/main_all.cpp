// main() of shadows_lessons, every lesson in one program (the bundle's, scripts/bundle.sh):
// it runs the lesson it is called as, through a link named 03_shadow_map_basic and so on.
#include <filesystem>

#include "run/runner.hpp"

int main(int argc, char** argv) {
  return shadows::runLessonMain(argc, argv, std::filesystem::path(argv[0]).filename().string());
}
