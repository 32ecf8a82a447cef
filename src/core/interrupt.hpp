// Ctrl-C as a request: the first SIGINT sets a flag that long jobs check
// between frames, stages and batches of lattice steps, so they stop within a
// fraction of a second with only complete files written; a second SIGINT
// ends the process at once, as usual, after removing the temporary files of
// writes under way (temporary_files.hpp).
#pragma once

#include <string>

namespace lbmshape::interrupt {

void installHandler();
bool requested();
// Throws Interrupted with `whatWasDone` if Ctrl-C was pressed.
void check(const std::string& whatWasDone);

}  // namespace lbmshape::interrupt
