#include "commands/commands.h"

#include <acute/core/errors.h>

#include <cstdio>
#include <exception>
#include <iostream>

namespace acute::cli {

void print_bad_triangles(const std::vector<BadTriangle>& remaining) {
  for (std::size_t i = 0; i < remaining.size() && i < 5; ++i) {
    const auto& t = remaining[i];
    std::fprintf(stderr, "  triangle (%.17g, %.17g) (%.17g, %.17g) (%.17g, %.17g): angles %.3f..%.3f\n", t.corners[0].x(),
                 t.corners[0].y(), t.corners[1].x(), t.corners[1].y(), t.corners[2].x(), t.corners[2].y(), t.min_angle_deg,
                 t.max_angle_deg);
  }
}

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
