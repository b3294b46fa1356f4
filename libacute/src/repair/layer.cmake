acute_add_layer(repair
  SOURCES
    src/repair/angle_bounds.cpp
    src/repair/clusters.cpp
    src/repair/joint_relaxation.cpp
    src/repair/region.cpp
    src/repair/relocation.cpp
    src/repair/repair.cpp
  DEPENDS acute_ops)
