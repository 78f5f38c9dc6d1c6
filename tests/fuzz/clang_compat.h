/* Included first in every file of the libFuzzer build: glibc's complex.h defines CMPLX only
 * for GCC >= 4.7, and clang presents itself as GCC 4.2. */
#if defined(__clang__) && !defined(CMPLX)
#define CMPLX(x, y) __builtin_complex((double)(x), (double)(y))
#endif
