# find_package(hlacore): the C++ APIs of an installed hlacore (python -m hlacore.config --cmake-dir).
#   target_link_libraries(my_federate PRIVATE hlacore::RTI-NG)    # HLA 1.3: RTI.hh, fedtime.hh, libRTI-NG, libFedTime
#   target_link_libraries(my_federate PRIVATE hlacore::rti1516e)  # IEEE 1516-2010: RTI/RTI1516.h, librti1516e,
#                                                                 # libfedtime1516e
# Also sets, for HLA 1.3, the variables of the FindRTI.cmake modules CERTI and OpenRTI users have: RTI_FOUND,
# RTI_INCLUDE_DIR, RTI_LIBRARIES, RTI_DEFINITIONS.
get_filename_component(_hlacore_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

# The two libraries of an API as imported targets, the first needing the second.
macro(_hlacore_api first second include_dir)
  if(EXISTS "${_hlacore_prefix}/lib/lib${first}.so" AND NOT TARGET hlacore::${first})
    add_library(hlacore::${second} SHARED IMPORTED)
    set_target_properties(hlacore::${second} PROPERTIES
      IMPORTED_LOCATION "${_hlacore_prefix}/lib/lib${second}.so"
      INTERFACE_INCLUDE_DIRECTORIES "${_hlacore_prefix}/include/${include_dir}")
    add_library(hlacore::${first} SHARED IMPORTED)
    set_target_properties(hlacore::${first} PROPERTIES
      IMPORTED_LOCATION "${_hlacore_prefix}/lib/lib${first}.so"
      INTERFACE_INCLUDE_DIRECTORIES "${_hlacore_prefix}/include/${include_dir}"
      INTERFACE_LINK_LIBRARIES hlacore::${second})
  endif()
endmacro()
_hlacore_api(RTI-NG FedTime hla13)
_hlacore_api(rti1516e fedtime1516e rti1516e)

if(TARGET hlacore::RTI-NG)
  set(RTI_FOUND TRUE)
  set(RTI_INCLUDE_DIR "${_hlacore_prefix}/include/hla13")
  set(RTI_LIBRARIES hlacore::RTI-NG hlacore::FedTime)
  set(RTI_DEFINITIONS -DRTI_USES_STD_FSTREAM)
endif()
set(hlacore_FOUND TRUE)
unset(_hlacore_prefix)
