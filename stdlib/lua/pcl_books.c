/* Pushers shared by the bindings of the books and the maps (pcl_books.h). */
#include "pcl_args.h"
#include "pcl_books.h"

void pcl_push_rows(lua_State *L, int nr, int nc, const double *m) {
    lua_createtable(L, nr, 0);
    for (int i = 0; i < nr; i++) {
        pcl_push_numbers(L, nc, m + (size_t)i * nc);
        lua_rawseti(L, -2, i + 1);
    }
}
