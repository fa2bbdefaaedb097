/* Space-separated tokens of the test host's text files (cases and outputs). */
#ifndef WINDOWS_TEST_TOKENS_H
#define WINDOWS_TEST_TOKENS_H

/* The next space-separated token of *s, terminated in place, or NULL. */
static inline char *token(char **s)
{
    char *p = *s;
    while (*p == ' ')
        ++p;
    if (*p == '\0')
        return NULL;
    char *start = p;
    while (*p != ' ' && *p != '\0')
        ++p;
    if (*p == ' ')
        *p++ = '\0';
    *s = p;
    return start;
}

#endif
