/* The one error line of every tool: "PROG: message" on stderr, then exit. Status 2 for bad input
 * from the user (an argument, a path, a file it names), 1 for a failure while running (a render
 * that crashed, a full disk): scripts and make tell the two apart by it. */
#ifndef DIE_H
#define DIE_H

#define DIE_USAGE 2   /* bad input */
#define DIE_RUNTIME 1 /* the run failed */

#include <stdarg.h>

_Noreturn void die(int status, const char *prog, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* The same with the arguments as a va_list (for functions that take their own "..."). */
_Noreturn void vdie(int status, const char *prog, const char *fmt, va_list ap) __attribute__((format(printf, 3, 0)));

#endif
