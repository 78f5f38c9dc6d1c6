/* The live page: pointcalc serve SCRIPT [--port N] (serve.c, docs/live.md). */
#ifndef PC_SERVE_H
#define PC_SERVE_H

/* Serve the page for the script on 127.0.0.1:port (0: any free port, printed on stdout) until
 * SIGINT or SIGTERM.  Returns the exit status. */
int serve_main(const char *script, int port);

#endif
