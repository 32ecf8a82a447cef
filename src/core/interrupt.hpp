// Ctrl-C as a request: the first SIGINT sets a flag that long jobs check
// between frames and stages, so they stop with only complete files written;
// a second SIGINT ends the process at once, as usual.
#pragma once

#include <string>

namespace lbmshape::interrupt {

void installHandler();
bool requested();
// Throws Interrupted with `whatWasDone` if Ctrl-C was pressed.
void check(const std::string& whatWasDone);

}  // namespace lbmshape::interrupt
