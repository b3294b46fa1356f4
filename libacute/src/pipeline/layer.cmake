acute_add_layer(pipeline
  SOURCES
    src/pipeline/mesher.cpp
  DEPENDS acute_refine acute_repair acute_cvt acute_delaunay)
