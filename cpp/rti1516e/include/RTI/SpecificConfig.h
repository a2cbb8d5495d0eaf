// hlacore's settings of the IEEE 1516-2010 C++ API (SISO-STD-004.1): what the two libraries export, and the
// owning pointer the factories return (std::unique_ptr: C++17 has no std::auto_ptr).
#ifndef RTI_SpecificConfig_h
#define RTI_SpecificConfig_h

#include <memory>

#define RTI_EXPORT __attribute__((visibility("default")))
#define RTI_EXPORT_FEDTIME __attribute__((visibility("default")))
#define RTI_UNIQUE_PTR std::unique_ptr

#endif
