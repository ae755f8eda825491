# make demo: the demos (issue 5). Included by the Makefile.
DEMO_BIN := $(BUILD)/tumble-trajectory
.PHONY: demo
$(DEMO_BIN): $(BUILD)/obj/demos/trajectory.o $(LIB_A)
	$(CC) -o $@ $< $(LIB_A) $(LDLIBS_ALL)

demo: $(DEMO_BIN)
	$(DEMO_BIN)

