/* A deadbeat running loop in C on slipmaps' exported maps. The controller plans every step with the
 * simple variable-stiffness map (`geyer-vs`, report 5.1): the touchdown angle and the stiffness
 * after the bottom k_d that take the next apex to 1.0 m above its ground at 4.0 m/s, over a ground
 * that steps up and down (known one step ahead; k_d != k_c adds or removes the energy a step
 * needs). The model plant runs the more accurate iterative map (`iterative`, 5.2) with the chosen
 * controls, so the controller corrects its model's error at every step.
 *
 * Build and run: make run (docs/c_export.md). SI units; the angle from the vertical,
 * counterclockwise positive. */
#include <math.h>
#include <stdio.h>

#include "slipmaps.h"
#include "slipmaps_deadbeat.h"

#define MODEL(field) SLIPMAPS_GEYER_VS_APEX_RETURN_##field
#define JAC(field) SLIPMAPS_GEYER_VS_APEX_RETURN_JACOBIAN_##field
#define STEPS 12

int main(void) {
    /* the human runner: 80 kg, 1 m leg, 20 kN/m, touchdown and liftoff at the rest length; each
       map's options at their defaults (slipmaps.h gives every field's meaning and default) */
    const slipmaps_geyer_vs_params model = {
        .m = 80.0, .l0 = 1.0, .k_c = 20000.0, .k_d = 20000.0, .g_s = 9.81, .g_f = 9.81,
        .q_r_td = 1.0, .q_r_lo = 1.0, .continuity = 2.0, .gravity = 0.0, .iterations = 100.0,
        .tol = 1e-12};
    slipmaps_iterative_params plant = {
        .m = 80.0, .l0 = 1.0, .k_c = 20000.0, .k_d = 20000.0, .g_s = 9.81, .g_f = 9.81,
        .q_r_td = 1.0, .q_r_lo = 1.0, .nodes = 3.0, .iterations = 6.0, .tol = 0.0};
    const double ground[STEPS] = {0.0, 0.1, 0.1, 0.2, 0.1, 0.0, -0.1, -0.1, 0.0, 0.05, 0.0, 0.0};
    const double target[2] = {1.0, 4.0}; /* next apex: height above its ground [m], speed [m/s] */
    const double *m = &model.m; /* the model's record as the vector p (its fields in order) */
    double x[MODEL(NX)], p[MODEL(NP)], out[SLIPMAPS_N_HEAD + MODEL(NOUT)];
    double height = 1.0, speed = 4.0, angle = 0.3, level = 0.0;
    slipmaps_deadbeat_settings s = {0};
    slipmaps_deadbeat_work work;
    int n, i;

    /* the controls: the touchdown angle (an input x) and k_d (a parameter p) */
    s.n_controls = 2;
    s.in_p[0] = 0, s.pos[0] = MODEL(X_Q_TH_TD), s.col[0] = JAC(WRT_Q_TH_TD);
    s.lo[0] = -1.2, s.hi[0] = 1.2, s.scale[0] = 10.0; /* rad */
    s.in_p[1] = 1, s.pos[1] = MODEL(P_K_D), s.col[1] = JAC(WRT_K_D);
    s.lo[1] = 10000.0, s.hi[1] = 40000.0, s.scale[1] = 20000.0; /* N/m */
    /* the targets: height and speed, weighted by 1/l0 and 1/sqrt(g l0) */
    s.targeted[0] = 1, s.targeted[1] = 1;
    s.weight[0] = 1.0 / model.l0, s.weight[1] = 1.0 / sqrt(model.g_f * model.l0);
    s.tol = 1e-9;
    s.n_out = MODEL(NOUT), s.n_wrt = JAC(NWRT), s.fd_step = 0.0;
    s.out_height = MODEL(OUT_APEX_HEIGHT), s.out_speed = MODEL(OUT_APEX_SPEED);
    s.kd_in_p = 1, s.kd_pos = -1; /* no energy budget */
    s.mass = model.m, s.g_f = model.g_f;
    s.max_evaluations = 200, s.broyden = 1, s.scan = 24;
    for (i = 0; i < MODEL(NP); i++) {
        p[i] = m[i];
    }

    printf("step  ground  apex h  apex v   angle      k_d  plan  model h  plant h  plant v\n");
    for (n = 0; n < STEPS; n++) {
        slipmaps_iterative_apex_return_zeroth_geyer_x px;
        slipmaps_iterative_apex_return_zeroth_geyer_out po;
        int status;
        /* this step's row: the apex, the last angle as the start, the next ground relative to this one */
        x[MODEL(X_B_Y_APEX)] = height;
        x[MODEL(X_B_XD_APEX)] = speed;
        x[MODEL(X_Q_TH_TD)] = angle;
        x[MODEL(X_GROUND)] = ground[n] - level;
        x[MODEL(X_RETRACTION_RATE)] = 0.0;
        p[MODEL(P_K_D)] = model.k_d; /* the nominal k_d as the start */
        if (slipmaps_deadbeat_solve(slipmaps_geyer_vs_apex_return_v,
                                    slipmaps_geyer_vs_apex_return_jacobian_v, x, MODEL(NX), p,
                                    MODEL(NP), target, &s, &work, out) != 0) {
            fprintf(stderr, "the solver refused the model\n");
            return 1;
        }
        if ((int)out[SLIPMAPS_HEAD_PLAN_STATUS] == SLIPMAPS_MAP_FAILED) {
            fprintf(stderr, "step %d: no controls the model can run (status %d)\n", n,
                    (int)out[SLIPMAPS_HEAD_MAP_STATUS]);
            return 1;
        }
        angle = out[SLIPMAPS_HEAD_U0];
        /* the plant: the iterative map with the chosen angle and k_d */
        px.b_y_apex = height, px.b_xd_apex = speed, px.q_th_td = angle;
        px.ground = ground[n] - level, px.retraction_rate = 0.0;
        plant.k_d = out[SLIPMAPS_HEAD_U1];
        status = slipmaps_iterative_apex_return_zeroth_geyer(&px, &plant, &po);
        if (status != SLIPMAPS_STATUS_OK) {
            fprintf(stderr, "step %d: the plant fell (status %d)\n", n, status);
            return 1;
        }
        printf("%4d %7.3f %7.4f %7.4f %7.4f %8.0f %5s %8.4f %8.4f %8.4f\n", n, ground[n], height,
               speed, angle, plant.k_d,
               (int)out[SLIPMAPS_HEAD_PLAN_STATUS] == SLIPMAPS_REACHED ? "ok" : "near",
               out[SLIPMAPS_N_HEAD + MODEL(OUT_APEX_HEIGHT)], po.apex_height, po.apex_speed);
        height = po.apex_height, speed = po.apex_speed, level = ground[n];
    }
    return 0;
}
