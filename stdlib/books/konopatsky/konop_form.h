/* The forms of the spec tables conic.ellipse, .hyperbola, .circle, .reparam, .sinusoid and
 * .cycloid: the curve of one form with the checks of its options, each failure explained by a
 * row that shows the values that broke it (why_call.h). */
#ifndef PC_KONOP_FORM_H
#define PC_KONOP_FORM_H

#include "konop_curves.h"
#include "why_call.h"

/* The forms beyond pc_kcurve's: (2.32) conjugate semi-diameters CA, CB; §2.1.1.6 the diameter
 * KA with B and lambda = par[0]; §2.1.8.1 the circular arc AB with tangents meeting at C. */
enum { PC_KF_CONJUGATE = PC_KC_NKINDS, PC_KF_DIAMETER, PC_KF_CIRCLE_ARC };

/* The first form of the spec table op ("conic.hyperbola": PC_KC_HYPERBOLA_ANGLE; its 'by'
 * choices are the forms from it in order), or -1 for another name. */
int pc_konop_form_base(const char *op);

/* The curve of form (a pc_kcurve_kind or a PC_KF_*) of the operation op in the simplex C A B
 * (c or k NULL: not given), its parameters par[0..npar-1] (NaN: not given), over [t0, t1] (NaN:
 * the book's range); NULL with *status and w the row that explains it: a missing point, delta
 * outside (0, pi), lambda outside (0, 1), a range beyond the form's real range; else the row of
 * pc_konop_why.  Made, w is the empty table. */
pc_curve *pc_konop_form(const char *op, int form, int dim, const double *c, const double *a,
                        const double *b, const double *k, const double *par, int npar, double t0,
                        double t1, int *status, pc_why_call *w);

#endif
