/* Creep-force lookup tables from C (librollcontact_cntc.so): open an HDF5 table written by
 * `rollcontact lookup -o FILE.h5` once, then evaluate it at every wheel and time step (about
 * 0.1 microsecond per call, thread-safe: a table is only read). See creep_lookup.hpp for the
 * normalisation: ksi_n = G c^2 ksi / (mu FN), eta_n likewise, phi_n = G c^3 phi / (mu FN),
 * c = sqrt(a b); results Fx/(mu FN), Fy/(mu FN), Mz/(mu FN c). Units mm, N, N/mm2, rad/mm. */
#ifndef ROLLCONTACT_CREEP_LOOKUP_H
#define ROLLCONTACT_CREEP_LOOKUP_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rc_creep_lookup rc_creep_lookup;

/* Opens a table; NULL when it cannot be read, with the reason in error[0..error_len-1]
 * (error may be NULL). */
rc_creep_lookup* rc_creep_lookup_open(const char* path, char* error, int error_len);

/* Releases a table (NULL is allowed). */
void rc_creep_lookup_close(rc_creep_lookup* table);

/* Normalised results at (a/b, ksi_n, eta_n, phi_n): out[0] Fx/(mu FN), out[1] Fy/(mu FN),
 * out[2] Mz/(mu FN c). Multilinear interpolation; outside the table see creep_lookup.hpp. */
void rc_creep_lookup_eval(const rc_creep_lookup* table, double a_over_b, double ksi_n, double eta_n,
                          double phi_n, double out[3]);

/* Physical units: semi-axes a, b [mm], FN [N], combined G [N/mm2], mu, creepages ksi, eta [-],
 * spin phi [rad/mm] -> out[0] Fx [N], out[1] Fy [N], out[2] Mz [N mm] on body 1 (the wheel). */
void rc_creep_lookup_forces(const rc_creep_lookup* table, double a, double b, double fn, double g,
                            double mu, double ksi, double eta, double phi, double out[3]);

#ifdef __cplusplus
}
#endif

#endif
