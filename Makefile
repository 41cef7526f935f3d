# Front doors. Both install what is missing first (scripts/install-deps), then build with CMake.
#   make demo   build Release, run samples/dam_break.json into out/dam_break/ with surface meshes
#               and draw its frames with the liquid as water
#               (out/dam_break/render/: a PNG per frame, and an MP4)
#   make test   build Release and run every test with ctest
#   make asan   build with ASan+UBSan (clang) and run the unit tests and a short run of each fuzz target
JOBS ?= $(shell nproc)

.PHONY: all deps build demo test asan bench clean

all: build

deps:
	@bash scripts/install-deps

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

demo: build
	./build/release/apps/upf/upf run samples/dam_break.json --out out/dam_break --render \
	  --set '/output/formats=["vtp","surface"]' --set /render/surface=true

test: build
	ctest --preset release -j $(JOBS)

asan: deps
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS) --target upf_unit_tests upf_surface_tests fuzz_scene fuzz_mesh fuzz_checkpoint
	ctest --preset asan -j $(JOBS)

bench: build
	./build/release/bench/bench_dam_break
	./build/release/bench/bench_column_collapse

clean:
	rm -rf build out
