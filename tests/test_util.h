/* Small helpers the cmocka test programs share. Include after <cmocka.h>. */
#ifndef SPANCAST_TESTS_TEST_UTIL_H
#define SPANCAST_TESTS_TEST_UTIL_H

#include <stdio.h>
#include <stdlib.h>

/* The whole file at path, NUL-terminated (the terminator is not counted in
 * *length, which may be NULL); fails the test when it cannot be read. */
static inline char *test_read_file(const char *path, size_t *length)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    long n = ftell(f);
    assert_true(n >= 0);
    assert_int_equal(fseek(f, 0, SEEK_SET), 0);
    char *text = malloc((size_t)n + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)n, f), (size_t)n);
    text[n] = 0;
    fclose(f);
    if (length)
        *length = (size_t)n;
    return text;
}

#endif
