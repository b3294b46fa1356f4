acute_add_layer(pipeline
  SOURCES
    src/pipeline/hub_patch.cpp
    src/pipeline/mesher.cpp
    src/pipeline/repair_mesh.cpp
  DEPENDS acute_refine acute_repair acute_cvt acute_delaunay acute_io)
