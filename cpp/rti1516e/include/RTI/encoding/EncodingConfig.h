// The integer and octet types the encoding helpers of IEEE 1516.1-2010's C++ API hold values in.
#ifndef RTI_EncodingConfig_h
#define RTI_EncodingConfig_h

#include <utility>
#include <vector>

namespace rti1516e {

typedef char Integer8;
typedef short Integer16;
typedef int Integer32;
typedef long long Integer64;
typedef Integer8 Octet;
// HLAoctetPairBE/LE: first is the high octet, second the low one.
typedef std::pair<Octet, Octet> OctetPair;

}  // namespace rti1516e

#endif
