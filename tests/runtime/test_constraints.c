/*
 * test_constraints.c - the constraints stage alone (constraints.c): plain
 * data, no character and no graph.
 *  - lookups: the style/action in force at an arc (the latest point at or
 *    before it, else the base one set from an arc), the next point after
 *    an arc;
 *  - edits: add checks the arc (finite, on the path) and the capacity,
 *    ids are positive and stay so when the counter wraps, move and remove
 *    find by id (NOT_FOUND otherwise), remove keeps insertion order (the
 *    earlier of two points at one arc wins), clear empties.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "constraints.h"

#define CAP 4u

typedef struct cons_buf {
  smgi_constraint items[CAP];
  smgi_constraints c;
} cons_buf;

static void init(cons_buf* b) {
  memset(b, 0, sizeof *b);
  b->c.items = b->items;
  b->c.capacity = CAP;
  b->c.next_id = 1;
  b->c.base_style = 0;
  b->c.base_action = 0;
  b->c.base_style_arc = -1.0f;
  b->c.base_action_arc = -1.0f;
}

static void test_lookups(void** state) {
  (void)state;
  cons_buf b;
  init(&b);
  uint32_t id;
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 4.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 1, &id),
                   SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 7.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 2, NULL),
                   SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 2.0f,
                                        SMGI_CONSTRAINT_SPLICE, 1, NULL),
                   SMG_OK);
  /* styles: base before 4 m, then 1, from 7 m on 2 (at the arc itself) */
  assert_int_equal(smgi_style_at(&b.c, 0.0f), 0);
  assert_int_equal(smgi_style_at(&b.c, 3.99f), 0);
  assert_int_equal(smgi_style_at(&b.c, 4.0f), 1);
  assert_int_equal(smgi_style_at(&b.c, 6.9f), 1);
  assert_int_equal(smgi_style_at(&b.c, 7.0f), 2);
  /* splice points do not change the style, transitions not the action */
  float arc = 0.0f;
  assert_int_equal(smgi_action_at(&b.c, 1.0f, &arc), 0);
  assert_true(arc == -1.0f);
  assert_int_equal(smgi_action_at(&b.c, 5.0f, &arc), 1);
  assert_true(arc == 2.0f);
  assert_int_equal(smgi_action_at(&b.c, 9.0f, NULL), 1);
  /* the base action (smg_character_set_action) counts from the arc it
   * was set at: a splice point further on overrides it, one before not */
  b.c.base_action = 3;
  b.c.base_action_arc = 1.0f;
  assert_int_equal(smgi_action_at(&b.c, 5.0f, &arc), 1);
  assert_true(arc == 2.0f);
  b.c.base_action_arc = 6.0f;
  assert_int_equal(smgi_action_at(&b.c, 6.5f, &arc), 3);
  assert_true(arc == 6.0f);
  /* next point strictly after an arc, any kind */
  assert_true(smgi_next_constraint_arc(&b.c, 0.0f) == 2.0f);
  assert_true(smgi_next_constraint_arc(&b.c, 2.0f) == 4.0f);
  assert_true(smgi_next_constraint_arc(&b.c, 4.5f) == 7.0f);
  assert_true(isinf(smgi_next_constraint_arc(&b.c, 7.0f)));
}

static void test_add_checks(void** state) {
  (void)state;
  cons_buf b;
  init(&b);
  uint32_t id = 77;
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, NAN,
                                        SMGI_CONSTRAINT_SPLICE, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, INFINITY,
                                        SMGI_CONSTRAINT_SPLICE, 1, &id),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, -0.5f,
                                        SMGI_CONSTRAINT_SPLICE, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, 5.5f,
                                        SMGI_CONSTRAINT_SPLICE, 1, &id),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(id, 77); /* untouched on failure */
  assert_int_equal(b.c.count, 0);
  /* the end of the path itself is on it */
  for (uint32_t i = 0; i < CAP; ++i)
    assert_int_equal(smgi_constraints_add(&b.c, 5.0f, 5.0f,
                                          SMGI_CONSTRAINT_SPLICE, 1, &id),
                     SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, 1.0f,
                                        SMGI_CONSTRAINT_SPLICE, 1, &id),
                   SMG_ERROR_CAPACITY);
  assert_int_equal(b.c.count, CAP);
}

static void test_ids_wrap(void** state) {
  (void)state;
  cons_buf b;
  init(&b);
  b.c.next_id = 0xffffffffu;
  uint32_t a = 0, c = 0;
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, 1.0f,
                                        SMGI_CONSTRAINT_SPLICE, 1, &a),
                   SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 5.0f, 2.0f,
                                        SMGI_CONSTRAINT_SPLICE, 1, &c),
                   SMG_OK);
  assert_int_equal(a, 0xffffffffu);
  assert_int_equal(c, 1u); /* never 0 */
}

static void test_move_remove_clear(void** state) {
  (void)state;
  cons_buf b;
  init(&b);
  uint32_t first, second, third;
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 3.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 1, &first),
                   SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 5.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 2, &second),
                   SMG_OK);
  assert_int_equal(smgi_constraints_add(&b.c, 10.0f, 5.0f,
                                        SMGI_CONSTRAINT_TRANSITION, 3, &third),
                   SMG_OK);
  /* equal arcs: the one added first wins */
  assert_int_equal(smgi_style_at(&b.c, 6.0f), 2);
  /* move: checked like add, by id */
  assert_int_equal(smgi_constraints_move(&b.c, 10.0f, first, 11.0f),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smgi_constraints_move(&b.c, 10.0f, 999u, 1.0f),
                   SMG_ERROR_NOT_FOUND);
  assert_int_equal(smgi_constraints_move(&b.c, 10.0f, first, 8.0f), SMG_OK);
  assert_int_equal(smgi_style_at(&b.c, 4.0f), 0);
  assert_int_equal(smgi_style_at(&b.c, 8.0f), 1);
  /* remove keeps the others in insertion order */
  assert_int_equal(smgi_constraints_remove(&b.c, 999u), SMG_ERROR_NOT_FOUND);
  assert_int_equal(smgi_constraints_remove(&b.c, first), SMG_OK);
  assert_int_equal(b.c.count, 2);
  assert_int_equal(smgi_constraints_remove(&b.c, first), SMG_ERROR_NOT_FOUND);
  assert_int_equal(b.c.items[0].id, second);
  assert_int_equal(b.c.items[1].id, third);
  assert_int_equal(smgi_style_at(&b.c, 8.0f), 2);
  assert_int_equal(smgi_constraints_remove(&b.c, second), SMG_OK);
  assert_int_equal(smgi_style_at(&b.c, 8.0f), 3);
  smgi_constraints_clear(&b.c);
  assert_int_equal(b.c.count, 0);
  assert_int_equal(smgi_style_at(&b.c, 8.0f), 0);
  assert_true(isinf(smgi_next_constraint_arc(&b.c, 0.0f)));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_lookups),
      cmocka_unit_test(test_add_checks),
      cmocka_unit_test(test_ids_wrap),
      cmocka_unit_test(test_move_remove_clear),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
