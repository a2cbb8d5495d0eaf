# find_package(hlacore): the HLA 1.3 C++ API of an installed hlacore (python -m hlacore.config --cmake-dir).
#   target_link_libraries(my_federate PRIVATE hlacore::RTI-NG)   # RTI.hh, fedtime.hh, libRTI-NG, libFedTime
# Also sets the variables of the FindRTI.cmake modules CERTI and OpenRTI users have: RTI_FOUND,
# RTI_INCLUDE_DIR, RTI_LIBRARIES, RTI_DEFINITIONS.
get_filename_component(_hlacore_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

if(NOT TARGET hlacore::FedTime)
  add_library(hlacore::FedTime SHARED IMPORTED)
  set_target_properties(hlacore::FedTime PROPERTIES
    IMPORTED_LOCATION "${_hlacore_prefix}/lib/libFedTime.so"
    INTERFACE_INCLUDE_DIRECTORIES "${_hlacore_prefix}/include/hla13")
  add_library(hlacore::RTI-NG SHARED IMPORTED)
  set_target_properties(hlacore::RTI-NG PROPERTIES
    IMPORTED_LOCATION "${_hlacore_prefix}/lib/libRTI-NG.so"
    INTERFACE_INCLUDE_DIRECTORIES "${_hlacore_prefix}/include/hla13"
    INTERFACE_LINK_LIBRARIES hlacore::FedTime)
endif()

set(RTI_FOUND TRUE)
set(RTI_INCLUDE_DIR "${_hlacore_prefix}/include/hla13")
set(RTI_LIBRARIES hlacore::RTI-NG hlacore::FedTime)
set(RTI_DEFINITIONS -DRTI_USES_STD_FSTREAM)
set(hlacore_FOUND TRUE)
unset(_hlacore_prefix)
