#include "commands/commands.h"

#include <acute/core/errors.h>

#include <exception>
#include <iostream>

namespace acute::cli {

int run_guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InvalidInput& e) {
    std::cerr << "acute: " << e.what() << "\n";
    return InvalidInputCode;
  } catch (const TopologyError& e) {
    std::cerr << "acute: " << e.what() << "\n";
    return InvalidInputCode;
  } catch (const IoError& e) {
    std::cerr << "acute: " << e.what() << "\n";
    return IoErrorCode;
  } catch (const std::bad_alloc&) {
    std::cerr << "acute: out of memory\n";
    return InternalErrorCode;
  } catch (const std::exception& e) {
    std::cerr << "acute: internal error: " << e.what() << "\n";
    return InternalErrorCode;
  }
}

}  // namespace acute::cli
