// A closed range [lower, upper] of a region's dimension (IEEE 1516.1-2010 §9).
#ifndef RTI_RangeBounds_h
#define RTI_RangeBounds_h

#include <RTI/SpecificConfig.h>

namespace rti1516e {

class RTI_EXPORT RangeBounds {
public:
    RangeBounds() = default;
    RangeBounds(unsigned long lowerBound, unsigned long upperBound) : _lowerBound(lowerBound), _upperBound(upperBound) {}
    unsigned long getLowerBound() const { return _lowerBound; }
    unsigned long getUpperBound() const { return _upperBound; }
    void setLowerBound(unsigned long lowerBound) { _lowerBound = lowerBound; }
    void setUpperBound(unsigned long upperBound) { _upperBound = upperBound; }

private:
    unsigned long _lowerBound = 0;
    unsigned long _upperBound = 0;
};

}  // namespace rti1516e

#endif
