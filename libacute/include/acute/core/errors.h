// Layer: core. The exceptions the library throws. Outcomes (e.g. bounds not met) are results, not errors.
#pragma once

#include <stdexcept>
#include <string>

namespace acute {

/// Base of every libacute exception.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The input is malformed or unusable: bad numbers, indices out of range, crossing segments...
/// The message is one line, starting with "file:line: " when a file is involved.
struct InvalidInput : Error {
  using Error::Error;
};

/// A file could not be read or written.
struct IoError : Error {
  using Error::Error;
};

/// A mesh is not a valid triangulation where one is required.
struct TopologyError : Error {
  using Error::Error;
};

/// A broken internal invariant (a bug): file:line in the message.
struct InternalError : Error {
  using Error::Error;
};

}  // namespace acute

#define ACUTE_STRINGIFY_(x) #x
#define ACUTE_STRINGIFY(x) ACUTE_STRINGIFY_(x)
/// Cheap always-on assertion: throws InternalError, never aborts or prints.
#define ACUTE_ASSERT(cond)                                                                         \
  do {                                                                                             \
    if (!(cond))                                                                                   \
      throw ::acute::InternalError(__FILE__ ":" ACUTE_STRINGIFY(__LINE__) ": assertion failed: " #cond); \
  } while (0)
