/* A first-order lag as an FMI 2 co-simulation FMU, for hlacore's tests: dx/dt = (u - x) / tau, y = x.
 *
 * doStep integrates exactly over the step with u held constant, so a run's result depends on the step size
 * only through the inputs. Two test parameters make it misbehave on purpose: from fail_time on, doStep
 * returns fmi2Error; from nan_time on, y becomes NaN. Its state (x, time) can be read, restored and
 * serialised, so a federation save includes it. Value references are those of modelDescription.xml. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

enum { VR_U = 0, VR_Y = 1, VR_TAU = 2, VR_X0 = 3, VR_FAIL_TIME = 4, VR_NAN_TIME = 5, VR_COUNT = 6 };

typedef struct {
    double values[VR_COUNT]; /* u, y (= x), tau, x0, fail_time, nan_time */
    double time;
} State;

typedef struct {
    State state;
    fmi2CallbackFunctions callbacks;
} Instance;

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[]) {
    (void)c; (void)on; (void)n; (void)categories;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                              const fmi2CallbackFunctions *callbacks, fmi2Boolean visible, fmi2Boolean logging) {
    (void)name; (void)guid; (void)location; (void)visible; (void)logging;
    if (type != fmi2CoSimulation) return NULL;
    Instance *instance = calloc(1, sizeof(Instance));
    if (!instance) return NULL;
    instance->callbacks = *callbacks;
    instance->state.values[VR_TAU] = 1.0;
    instance->state.values[VR_FAIL_TIME] = INFINITY;
    instance->state.values[VR_NAN_TIME] = INFINITY;
    return instance;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolDefined, fmi2Real tol, fmi2Real start,
                               fmi2Boolean stopDefined, fmi2Real stop) {
    (void)tolDefined; (void)tol; (void)stopDefined; (void)stop;
    ((Instance *)c)->state.time = start;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    State *s = &((Instance *)c)->state;
    s->values[VR_Y] = s->values[VR_X0];
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component c) { (void)c; return fmi2Error; }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
    State *s = &((Instance *)c)->state;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= VR_COUNT) return fmi2Error;
        value[i] = s->values[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
    State *s = &((Instance *)c)->state;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= VR_COUNT || vr[i] == VR_Y) return fmi2Error;
        s->values[vr[i]] = value[i];
    }
    return fmi2OK;
}

#define NO_VARIABLES_OF_TYPE(Kind, Type)                                                                    \
    fmi2Status fmi2Get##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, Type value[]) {      \
        (void)c; (void)vr; (void)value;                                                                     \
        return n == 0 ? fmi2OK : fmi2Error;                                                                 \
    }                                                                                                       \
    fmi2Status fmi2Set##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, const Type value[]) { \
        (void)c; (void)vr; (void)value;                                                                     \
        return n == 0 ? fmi2OK : fmi2Error;                                                                 \
    }
NO_VARIABLES_OF_TYPE(Integer, fmi2Integer)
NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
NO_VARIABLES_OF_TYPE(String, fmi2String)

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state) {
    State *copy = *state ? (State *)*state : malloc(sizeof(State));
    if (!copy) return fmi2Error;
    *copy = ((Instance *)c)->state;
    *state = copy;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    ((Instance *)c)->state = *(State *)state;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state) {
    (void)c;
    free(*state);
    *state = NULL;
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t *size) {
    (void)c; (void)state;
    *size = sizeof(State);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    (void)c;
    if (size < sizeof(State)) return fmi2Error;
    memcpy(bytes, state, sizeof(State));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state) {
    (void)c;
    if (size != sizeof(State)) return fmi2Error;
    State *copy = malloc(sizeof(State));
    if (!copy) return fmi2Error;
    memcpy(copy, bytes, sizeof(State));
    *state = copy;
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference unknown[], size_t nUnknown,
                                        const fmi2ValueReference known[], size_t nKnown, const fmi2Real dv[],
                                        fmi2Real df[]) {
    (void)c; (void)unknown; (void)nUnknown; (void)known; (void)nKnown; (void)dv; (void)df;
    return fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)c; (void)vr; (void)n; (void)order; (void)value;
    return fmi2Error;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)c; (void)vr; (void)n; (void)order; (void)value;
    return fmi2Error;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean noSetPrior) {
    (void)noSetPrior;
    State *s = &((Instance *)c)->state;
    if (t >= s->values[VR_FAIL_TIME]) return fmi2Error;
    double x = s->values[VR_Y], u = s->values[VR_U];
    x = u + (x - u) * exp(-h / s->values[VR_TAU]);
    s->values[VR_Y] = t + h >= s->values[VR_NAN_TIME] ? NAN : x;
    s->time = t + h;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)c; (void)s; (void)value;
    return fmi2Discard;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    State *state = &((Instance *)c)->state;
    if (s != fmi2LastSuccessfulTime) return fmi2Discard;
    *value = state->time;
    return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    (void)c; (void)s; (void)value;
    return fmi2Discard;
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    (void)c; (void)s; (void)value;
    return fmi2Discard;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    (void)c; (void)s; (void)value;
    return fmi2Discard;
}
