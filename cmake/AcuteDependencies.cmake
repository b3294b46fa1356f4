# The one place where third-party packages are looked up.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenMesh REQUIRED)
find_package(nlohmann_json 3 REQUIRED)

# OpenMesh exports un-namespaced targets; wrap them once.
if(NOT TARGET acute_openmesh)
  add_library(acute_openmesh INTERFACE)
  target_link_libraries(acute_openmesh INTERFACE OpenMeshCore)
  target_compile_definitions(acute_openmesh INTERFACE _USE_MATH_DEFINES)
endif()
