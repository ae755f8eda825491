# make valgrind: memcheck over the whole test suite (issue 7). Included by the Makefile.
# Every suite of `make test` (unit, reference and the EXTRA_TEST_BIN hook) runs
# in-process (CK_FORK=no, so memcheck sees every test's allocations) under
# memcheck; a suite fails on any memory error or on a definite or indirect leak.
# tools/valgrind.supp suppresses exactly one known leak outside tumble (OSMesa's
# context creation), nothing else. Logs: $(BUILD)/valgrind/<suite>.log.
VALGRIND_SUPP := tools/valgrind.supp
VALGRIND_FLAGS := --tool=memcheck --error-exitcode=97 --leak-check=full --show-leak-kinds=definite,indirect \
  --errors-for-leak-kinds=definite,indirect --suppressions=$(VALGRIND_SUPP) --num-callers=30
VALGRIND_BIN = $(UNIT_BIN) $(REF_BIN) $(EXTRA_TEST_BIN)

.PHONY: valgrind
valgrind:
	@tools/deps.sh test valgrind $(EXTRA_TEST_DEPS)
	@$(MAKE) --no-print-directory $(VALGRIND_BIN)
	@mkdir -p $(BUILD)/valgrind
	@failed=""; n=0; for t in $(VALGRIND_BIN); do n=$$((n + 1)); log=$(BUILD)/valgrind/$$(basename $$t).log; \
	  if CK_FORK=no valgrind $(VALGRIND_FLAGS) --log-file=$$log $$t >$$log.out 2>&1; then r=ok; else r=FAILED; failed="$$failed $$t"; fi; \
	  echo "== $$t: $$r; $$(grep -h 'ERROR SUMMARY' $$log | sed 's/==[0-9]*== //'); $$(grep -h 'definitely lost:' $$log | sed 's/==[0-9]*== *//')"; \
	  [ $$r = ok ] || tail -n 30 $$log.out; done; \
	echo "== valgrind: $$n suites run, $$(echo $$failed | wc -w) failed$$failed"; [ -z "$$failed" ]
