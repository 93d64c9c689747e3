// The one error type facet throws for bad input and failed operations.
//
// Its message is a single line meant for the user ("scene.json: camera.width must be a
// positive integer, got -4"); the CLI prints it after "facet: error: " and exits non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace facet {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace facet
