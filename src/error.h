// The project's error for bad input: a file, key, flag or value a user got wrong.
//
// Its message is one line that names the bad input (the file, the key, the value); programs
// print it as "<program>: error: <message>" and exit with status 2. Internal logic errors use
// the standard exceptions instead.
#pragma once

#include <stdexcept>
#include <string>

namespace colav {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace colav
