// The logical time interfaces' destructors (pure, so defined here) and their stream operators.
#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/LogicalTimeInterval.h>

#include <ostream>

namespace rti1516e {

LogicalTime::~LogicalTime() {}
LogicalTimeInterval::~LogicalTimeInterval() {}
LogicalTimeFactory::~LogicalTimeFactory() {}

std::wostream& operator<<(std::wostream& stream, LogicalTime const& time) { return stream << time.toString(); }
std::wostream& operator<<(std::wostream& stream, LogicalTimeInterval const& interval) {
    return stream << interval.toString();
}

}  // namespace rti1516e
