// HLAfloat64TimeFactory: one of the standard time types, declared with the other in RTI/time/HLAtimeTypes.h.
#ifndef RTI_HLAfloat64TimeFactory_h
#define RTI_HLAfloat64TimeFactory_h

#include <RTI/time/HLAtimeTypes.h>

#endif
