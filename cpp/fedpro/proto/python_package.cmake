# Turns protoc's Python output in DIR into the package hlacore.fedpro._proto (CMakeLists.txt runs it after
# protoc --python_out --pyi_out): protoc writes `import datatypes_pb2 as ...`, a top-level module that does
# not exist once installed, so each import of a sibling *_pb2 module becomes `from . import ... as ...`, in
# the modules and in their type stubs; and it writes the package's __init__.py.
#   cmake -DDIR=<protoc's output directory> -P python_package.cmake
if(NOT DIR)
  message(FATAL_ERROR "python_package.cmake: pass -DDIR=<the directory of the generated modules>")
endif()
file(GLOB generated ${DIR}/*_pb2.py ${DIR}/*_pb2.pyi)
if(NOT generated)
  message(FATAL_ERROR "python_package.cmake: no *_pb2.py in ${DIR}")
endif()
foreach(path IN LISTS generated)
  file(READ ${path} text)
  # A newline in front, so that an import on the first line (the stubs') matches like any other.
  string(REGEX REPLACE "\nimport ([A-Za-z0-9_]+_pb2) as " "\nfrom . import \\1 as " text "\n${text}")
  if(text MATCHES "\n(import [A-Za-z0-9_]+_pb2|from [A-Za-z0-9_]+_pb2 import)")
    message(FATAL_ERROR "python_package.cmake: ${path} still imports a sibling module by its top-level name: "
                        "protoc's output changed; update this script")
  endif()
  string(SUBSTRING "${text}" 1 -1 text)
  file(WRITE ${path} "${text}")
endforeach()
file(WRITE ${DIR}/__init__.py
"\"\"\"The HLA 4 Federate Protocol's messages (IEEE 1516.1-2025), package rti1516_2025.fedpro: generated at build
time by protoc from cpp/fedpro/proto. datatypes_pb2 holds the data types, RTIambassador_pb2 the calls
(CallRequest, CallResponse) and FederateAmbassador_pb2 the callbacks (CallbackRequest, CallbackResponse).\"\"\"
")
