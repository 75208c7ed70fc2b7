/* jsonstr.h -- a C string as a JSON string, for the reports.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Reports name files (the scene, the change file, a matrix), and a file
 * name may hold any byte but NUL.  RFC 8259, section 7: inside a JSON
 * string the quotation mark, the reverse solidus and the control
 * characters U+0000 to U+001F must be escaped; every other byte is written
 * as it is (a name that is not UTF-8 stays as the system gave it).
 */
#ifndef RAD_JSONSTR_H
#define RAD_JSONSTR_H

#include <stdio.h>

/* Write s quoted and escaped, or null when s is NULL. */
void radi_json_string(FILE *out, const char *s);

#endif /* RAD_JSONSTR_H */
