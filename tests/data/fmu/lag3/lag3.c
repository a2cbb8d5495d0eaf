/* The first-order lag of ../lag2 as an FMI 3 co-simulation FMU: dx/dt = (u - x) / tau, y = x, doStep exact with
 * u held; its instance as the other test FMUs' (../fmi3_instance.h). The services a co-simulation of Float64
 * variables does not use are in unsupported.c. Value references are those of modelDescription.xml. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"

enum { VR_TIME = 0, VR_U = 1, VR_Y = 2, VR_TAU = 3, VR_X0 = 4, VR_COUNT = 5 };

typedef struct {
    double values[VR_COUNT]; /* time, u, y (= x), tau, x0 */
} State;

static void state_start(State *s) { s->values[VR_TAU] = 1.0; }

#include "../fmi3_instance.h"

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean tolDefined, fmi3Float64 tol,
                                       fmi3Float64 start, fmi3Boolean stopDefined, fmi3Float64 stop) {
    (void)tolDefined; (void)tol; (void)stopDefined; (void)stop;
    ((State *)instance)->values[VR_TIME] = start;
    return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    State *s = instance;
    s->values[VR_Y] = s->values[VR_X0];
    return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, fmi3Float64 values[],
                          size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= VR_COUNT) return fmi3Error;
        values[i] = s->values[vr[i]];
    }
    return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t n, const fmi3Float64 values[],
                          size_t nValues) {
    State *s = instance;
    if (n != nValues) return fmi3Error;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= VR_COUNT || vr[i] == VR_Y || vr[i] == VR_TIME) return fmi3Error;
        s->values[vr[i]] = values[i];
    }
    return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 t, fmi3Float64 h, fmi3Boolean noSetPrior,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminate, fmi3Boolean *earlyReturn,
                      fmi3Float64 *lastSuccessfulTime) {
    (void)noSetPrior;
    State *s = instance;
    double x = s->values[VR_Y], u = s->values[VR_U];
    s->values[VR_Y] = u + (x - u) * exp(-h / s->values[VR_TAU]);
    s->values[VR_TIME] = t + h;
    *eventHandlingNeeded = fmi3False;
    *terminate = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = t + h;
    return fmi3OK;
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *state) {
    State *copy = *state ? (State *)*state : malloc(sizeof(State));
    if (!copy) return fmi3Error;
    *copy = *(State *)instance;
    *state = copy;
    return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState state) {
    *(State *)instance = *(State *)state;
    return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *state) {
    (void)instance;
    free(*state);
    *state = NULL;
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState state, size_t *size) {
    (void)instance; (void)state;
    *size = sizeof(State);
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState state, fmi3Byte bytes[], size_t size) {
    (void)instance;
    if (size < sizeof(State)) return fmi3Error;
    memcpy(bytes, state, sizeof(State));
    return fmi3OK;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte bytes[], size_t size,
                                   fmi3FMUState *state) {
    (void)instance;
    if (size != sizeof(State)) return fmi3Error;
    State *copy = malloc(sizeof(State));
    if (!copy) return fmi3Error;
    memcpy(copy, bytes, sizeof(State));
    *state = copy;
    return fmi3OK;
}
