#pragma once
// Errors of the core library. Every function that can fail on user input throws Error with a
// message that names the problem (file, line, section, count); hosts show what() as is.
#include <stdexcept>
#include <string>

namespace slicereuse {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when a Progress callback asks to stop.
struct Cancelled : Error {
  Cancelled() : Error("cancelled by the user") {}
};

}  // namespace slicereuse
