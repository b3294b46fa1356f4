acute_add_layer(refine
  SOURCES
    src/refine/refine.cpp
  DEPENDS acute_ops)
