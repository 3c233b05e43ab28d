// Bad input in a scene or a --set (exit code 2): the message names the file, the key, the value
// and what is allowed.
#pragma once

#include <stdexcept>

namespace impact {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace impact
