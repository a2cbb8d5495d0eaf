/* An FMI 2.0 co-simulation FMU from a model of numbers, in a few functions (docs/fmu.md, "Writing an FMU in C").
 * The model's C file defines, then includes this header once:
 *
 *     enum { VR_U, VR_Y, ..., MODEL_VALUES };          value references 0 .. MODEL_VALUES - 1, as in the
 *                                                       model description
 *     static void model_start(double v[]);              start values, at instantiation
 *     static void model_initialize(double v[]);         calculated values, at the end of initialisation mode
 *     static int model_settable(fmi2ValueReference vr); whether fmi2SetReal may set vr (inputs, parameters)
 *     static int model_step(double v[], double t, double h);  one step from t; 0, or -1 when it fails
 *
 * and, when an output depends directly on an input (direct feedthrough: the model description lists the input
 * among the output's dependencies), `#define MODEL_OUTPUTS model_outputs` and
 *
 *     static void model_outputs(double v[]);            the outputs from the inputs set, before each get
 *
 * The values are Reals, except those `#define MODEL_INTEGER(vr)` is true for: Integer and Enumeration variables,
 * whole numbers in v[], which fmi2GetInteger and fmi2SetInteger reach (and fmi2GetReal and fmi2SetReal do not).
 *
 * Everything else FMI 2 asks of a co-simulation FMU is here: its state (the values and the time) can be got,
 * set and serialised, so a federation save includes it; Boolean and String variables do not exist;
 * derivatives and asynchronous steps are refused, as FMI 2 lets an FMU that does not declare them. */
#ifndef HLACORE_FMI2_H
#define HLACORE_FMI2_H

#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

typedef struct {
    double values[MODEL_VALUES];
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
    model_start(instance->state.values);
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
    model_initialize(((Instance *)c)->state.values);
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component c) { (void)c; return fmi2Error; }

#ifndef MODEL_INTEGER
#define MODEL_INTEGER(vr) 0
#endif
#ifdef MODEL_OUTPUTS
#define HLACORE_OUTPUTS(v) MODEL_OUTPUTS(v)
#else
#define HLACORE_OUTPUTS(v) (void)(v)
#endif

/* fmi2Get<Kind> and fmi2Set<Kind> for the value references `is_kind` is true for. */
#define HLACORE_VARIABLES_OF_TYPE(Kind, Type, is_kind)                                                       \
    fmi2Status fmi2Get##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, Type value[]) {      \
        State *s = &((Instance *)c)->state;                                                                 \
        HLACORE_OUTPUTS(s->values);                                                                         \
        for (size_t i = 0; i < n; i++) {                                                                    \
            if (vr[i] >= MODEL_VALUES || !(is_kind)) return fmi2Error;                                      \
            value[i] = (Type)s->values[vr[i]];                                                              \
        }                                                                                                   \
        return fmi2OK;                                                                                      \
    }                                                                                                       \
    fmi2Status fmi2Set##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, const Type value[]) { \
        State *s = &((Instance *)c)->state;                                                                 \
        for (size_t i = 0; i < n; i++) {                                                                    \
            if (vr[i] >= MODEL_VALUES || !(is_kind) || !model_settable(vr[i])) return fmi2Error;            \
            s->values[vr[i]] = value[i];                                                                    \
        }                                                                                                   \
        return fmi2OK;                                                                                      \
    }
HLACORE_VARIABLES_OF_TYPE(Real, fmi2Real, !MODEL_INTEGER(vr[i]))
HLACORE_VARIABLES_OF_TYPE(Integer, fmi2Integer, MODEL_INTEGER(vr[i]))

#define HLACORE_NO_VARIABLES_OF_TYPE(Kind, Type)                                                            \
    fmi2Status fmi2Get##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, Type value[]) {      \
        (void)c; (void)vr; (void)value;                                                                     \
        return n == 0 ? fmi2OK : fmi2Error;                                                                 \
    }                                                                                                       \
    fmi2Status fmi2Set##Kind(fmi2Component c, const fmi2ValueReference vr[], size_t n, const Type value[]) { \
        (void)c; (void)vr; (void)value;                                                                     \
        return n == 0 ? fmi2OK : fmi2Error;                                                                 \
    }
HLACORE_NO_VARIABLES_OF_TYPE(Boolean, fmi2Boolean)
HLACORE_NO_VARIABLES_OF_TYPE(String, fmi2String)

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
    if (model_step(s->values, t, h) != 0) return fmi2Error;
    s->time = t + h;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    (void)c; (void)s; (void)value;
    return fmi2Discard;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    if (s != fmi2LastSuccessfulTime) return fmi2Discard;
    *value = ((Instance *)c)->state.time;
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

#endif
