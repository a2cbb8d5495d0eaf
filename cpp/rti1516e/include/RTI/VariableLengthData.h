// A run of bytes as IEEE 1516.1-2010's C++ API passes values, tags and encodings: a copy of its own
// (setData, the copy constructor), a view of the caller's bytes (setDataPointer: they must outlive it), or
// the caller's buffer taken over (takeDataPointer: freed with the function given, else delete[]).
#ifndef RTI_VariableLengthData_h
#define RTI_VariableLengthData_h

#include <RTI/SpecificConfig.h>

#include <stddef.h>

namespace rti1516e {

typedef void (*VariableLengthDataDeleteFunction)(void* data);

class RTI_EXPORT VariableLengthData {
public:
    VariableLengthData() = default;
    VariableLengthData(void const* inData, size_t inSize);
    VariableLengthData(VariableLengthData const& rhs);
    ~VariableLengthData();
    VariableLengthData& operator=(VariableLengthData const& rhs);

    void const* data() const { return _data; }
    size_t size() const { return _size; }
    void setData(void const* inData, size_t inSize);
    void setDataPointer(void* inData, size_t inSize);
    void takeDataPointer(void* inData, size_t inSize, VariableLengthDataDeleteFunction func = 0);

private:
    void release();

    void* _data = nullptr;
    size_t _size = 0;
    bool _owned = false;  // _data is freed by _deleter, or by delete[] when that is null
    VariableLengthDataDeleteFunction _deleter = nullptr;
};

}  // namespace rti1516e

#endif
