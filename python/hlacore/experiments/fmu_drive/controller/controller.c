/* A waypoint controller for a differential-drive robot, as an FMI 2 co-simulation FMU over hlacore's skeleton
 * (hlacore/fmu/c/hlacore_fmi2.h): the FMU of `python -m hlacore.experiments.fmu_drive` (docs/fmu.md).
 *
 * Each step from t, with the pose (x, y, theta) held at its value of t: when the robot is within tolerance of
 * its waypoint, the next becomes the target; the command steers towards the target (angular speed
 * proportional to the heading error) and drives at a speed proportional to the distance, scaled down by the
 * cosine of the heading error (nothing while facing away), both bounded; after the last waypoint it stops.
 * Outputs v, w and the target's index (4: done) hold over the next step. */
#include <math.h>

#include "fmi2Functions.h"

enum {
    VR_X, VR_Y, VR_THETA,                                           /* inputs: the robot's pose */
    VR_V, VR_W, VR_WAYPOINT,                                        /* outputs */
    VR_K_LINEAR, VR_K_ANGULAR, VR_V_MAX, VR_W_MAX, VR_TOLERANCE,    /* parameters */
    VR_WAYPOINTS,                                                   /* x1 y1 ... x4 y4 */
    MODEL_VALUES = VR_WAYPOINTS + 8
};
#define WAYPOINTS 4

static void model_start(double v[]) {
    static const double square[2 * WAYPOINTS] = {2, 0, 2, 2, 0, 2, 0, 0};
    v[VR_K_LINEAR] = 1.0;
    v[VR_K_ANGULAR] = 2.0;
    v[VR_V_MAX] = 0.5;
    v[VR_W_MAX] = 1.2;
    v[VR_TOLERANCE] = 0.1;
    for (int i = 0; i < 2 * WAYPOINTS; i++) v[VR_WAYPOINTS + i] = square[i];
}

static void model_initialize(double v[]) { v[VR_V] = v[VR_W] = v[VR_WAYPOINT] = 0.0; }

static int model_settable(fmi2ValueReference vr) { return vr < VR_V || vr >= VR_K_LINEAR; }

static double bound(double value, double limit) { return fmax(-limit, fmin(limit, value)); }

static int model_step(double v[], double t, double h) {
    (void)t; (void)h;
    int target = (int)v[VR_WAYPOINT];
    double dx = 0, dy = 0;
    for (; target < WAYPOINTS; target++) {
        dx = v[VR_WAYPOINTS + 2 * target] - v[VR_X];
        dy = v[VR_WAYPOINTS + 2 * target + 1] - v[VR_Y];
        if (hypot(dx, dy) >= v[VR_TOLERANCE]) break;
    }
    v[VR_WAYPOINT] = target;
    if (target == WAYPOINTS) {
        v[VR_V] = v[VR_W] = 0.0;
        return 0;
    }
    double error = remainder(atan2(dy, dx) - v[VR_THETA], 2 * M_PI);
    v[VR_W] = bound(v[VR_K_ANGULAR] * error, v[VR_W_MAX]);
    v[VR_V] = bound(v[VR_K_LINEAR] * hypot(dx, dy), v[VR_V_MAX]) * fmax(0.0, cos(error));
    return 0;
}

#include "hlacore_fmi2.h"
