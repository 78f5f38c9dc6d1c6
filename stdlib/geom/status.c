/* The messages of the status codes (status.h). */
#include "status.h"

const char *pc_strerror(int status) {
    switch (status) {
    case PC_OK: return "ok";
    case PC_IMPROPER: return "the point is at infinity (weight 0)";
    case PC_EZERO: return "zero vector where a direction is needed";
    case PC_ECOINCIDENT: return "the points coincide";
    case PC_ENOTCOLLINEAR: return "the points are not collinear";
    case PC_ECOLLINEAR: return "the points are dependent (degenerate simplex)";
    case PC_ESAME_LINE: return "the lines coincide";
    case PC_ESKEW: return "the lines are skew";
    case PC_ESINGULAR: return "the map is singular";
    case PC_EWEIGHT: return "the weight is neither 1 (a point) nor 0 (a vector)";
    case PC_EDIM: return "dimensions do not fit";
    case PC_ENONFINITE: return "NaN or infinite value";
    case PC_EDOMAIN: return "parameter outside its domain";
    case PC_ENOBRACKET: return "no sign change: the interval brackets no root";
    case PC_EPOLE: return "evaluated at the pole of the map";
    case PC_EARG: return "an argument is out of range";
    case PC_ENOMEM: return "out of memory";
    case PC_EIO: return "cannot write the file";
    case PC_ENOCONVERGE: return "the iteration did not converge";
    case PC_EDOMAIN2: return "a second parameter outside its domain";
    case PC_EDOMAIN3: return "a third parameter outside its domain";
    }
    return "unknown error";
}
