// The main() of every lesson binary: the lesson registers itself, the runner does the rest.
#include "run/runner.hpp"

int main(int argc, char** argv) {
  return shadows::runLessonMain(argc, argv);
}
