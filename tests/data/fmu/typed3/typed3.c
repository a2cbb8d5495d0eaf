/* FMI 3's other types through the federation, for hlacore's tests: an FMI 3 co-simulation FMU with one input and
 * one output of each of Float32, Int8, UInt8, Int16, UInt16, UInt32, Int64, UInt64, String, Binary and an
 * Enumeration (got and set as an Int64); each step copies every input to its output. Input k has value reference
 * 1 + 2k, its output 2 + 2k (modelDescription.xml).
 * Its instance is the other test FMUs' (../fmi3_instance.h); the services it does not offer are in unsupported.c. */
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"

#define NUMERIC(X) \
    X(Float32, fmi3Float32, 0) X(Int8, fmi3Int8, 1) X(UInt8, fmi3UInt8, 2) X(Int16, fmi3Int16, 3) \
    X(UInt16, fmi3UInt16, 4) X(UInt32, fmi3UInt32, 5) X(Int64, fmi3Int64, 6) X(UInt64, fmi3UInt64, 7)
enum { INT64 = 6, STRING = 8, BINARY = 9, ENUMERATION = 10, CAPACITY = 64 };
#define IN(k) (1u + 2u * (k))
#define OUT(k) (2u + 2u * (k))

typedef struct {
#define FIELD(Name, Type, k) Type Name[4]; /* the input, the output (Int64: then the Enumeration's) */
    NUMERIC(FIELD)
    char string[2][CAPACITY];
    size_t binary_size[2];
    unsigned char binary[2][CAPACITY];
} State;

/* Where the value of vr is among those of type k: 0 the input, 1 the output (for Int64 also 2 and 3, the
 * Enumeration's), -1 none. */
static int side(fmi3ValueReference vr, unsigned k) {
    if (k == INT64 && (vr == IN(ENUMERATION) || vr == OUT(ENUMERATION))) return 2 + (vr == OUT(ENUMERATION));
    return vr == IN(k) ? 0 : vr == OUT(k) ? 1 : -1;
}

#define ACCESSORS(Name, Type, k)                                                                                 \
    fmi3Status fmi3Get##Name(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, Type values[],    \
                             size_t nValues) {                                                                 \
        State *s = instance;                                                                                   \
        if (n != nValues) return fmi3Error;                                                                    \
        for (size_t i = 0; i < n; i++) {                                                                       \
            int which = side(vr[i], k);                                                                        \
            if (which < 0) return fmi3Error;                                                                   \
            values[i] = s->Name[which];                                                                        \
        }                                                                                                      \
        return fmi3OK;                                                                                         \
    }                                                                                                          \
    fmi3Status fmi3Set##Name(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, const Type values[], \
                             size_t nValues) {                                                                 \
        State *s = instance;                                                                                   \
        if (n != nValues) return fmi3Error;                                                                    \
        for (size_t i = 0; i < n; i++) {                                                                       \
            int which = side(vr[i], k);                                                                        \
            if (which != 0 && which != 2) return fmi3Error;                                                    \
            s->Name[which] = values[i];                                                                        \
        }                                                                                                      \
        return fmi3OK;                                                                                         \
    }
NUMERIC(ACCESSORS)

fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, fmi3String values[],
                         size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        int which = side(vr[i], STRING);
        if (which < 0) return fmi3Error;
        values[i] = s->string[which];
    }
    return fmi3OK;
}

fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, const fmi3String values[],
                         size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        if (side(vr[i], STRING) != 0 || strlen(values[i]) >= CAPACITY) return fmi3Error;
        strcpy(s->string[0], values[i]);
    }
    return fmi3OK;
}

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, size_t sizes[],
                         fmi3Binary values[], size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        int which = side(vr[i], BINARY);
        if (which < 0) return fmi3Error;
        sizes[i] = s->binary_size[which];
        values[i] = s->binary[which];
    }
    return fmi3OK;
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, const size_t sizes[],
                         const fmi3Binary values[], size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        if (side(vr[i], BINARY) != 0 || sizes[i] > CAPACITY) return fmi3Error;
        memcpy(s->binary[0], values[i], sizes[i]);
        s->binary_size[0] = sizes[i];
    }
    return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 t, fmi3Float64 h, fmi3Boolean noSetPrior,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminate, fmi3Boolean *earlyReturn,
                      fmi3Float64 *lastSuccessfulTime) {
    (void)noSetPrior;
    State *s = instance;
#define COPY(Name, Type, k) s->Name[1] = s->Name[0], s->Name[3] = s->Name[2];
    NUMERIC(COPY)
    memcpy(s->string[1], s->string[0], CAPACITY);
    memcpy(s->binary[1], s->binary[0], CAPACITY);
    s->binary_size[1] = s->binary_size[0];
    *eventHandlingNeeded = *terminate = *earlyReturn = fmi3False;
    *lastSuccessfulTime = t + h;
    return fmi3OK;
}

static void state_start(State *s) { (void)s; }

#include "../fmi3_instance.h"

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean tolDefined, fmi3Float64 tol,
                                       fmi3Float64 start, fmi3Boolean stopDefined, fmi3Float64 stop) {
    (void)instance; (void)tolDefined; (void)tol; (void)start; (void)stopDefined; (void)stop;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) { (void)instance; return fmi3OK; }
