// Frame3DD's example B (2015) as text, shared by the reader's tests (tests/io/frame3dd_test.cpp)
// and the command line's (tests/cli/frame3dd_command_test.cpp), with the frequencies it publishes.
#pragma once

#include <array>

namespace kinestat::io {

// Frame3DD's example B as published with Frame3DD 20140514+ (pslack/frame3dd, examples/exB.out of
// 2015): the pyramid again, now 1 m high with steel members (E = 200000 MPa, shear flag 1), self-weight
// in every case and the geometric stiffness flag 1 (Frame3DD's second-order analysis). Its data
// retyped from the input that exB.out echoes (members 1 and 4 run from the base to the apex there),
// in N-mm (density in t/mm^3, gravity in mm/s^2), with its modal data (6 modes, consistent masses,
// tolerance 1e-9, 0.1 t at the apex, no extra element mass).
constexpr const char* kExampleB2015 = R"(Example B: a pyramid-shaped frame (N mm ton)
5
1	0.0	0.0	1000	0.0
2	-1200	-900	0.0	0.0
3	 1200	-900	0.0	0.0
4	 1200	 900	0.0	0.0
5	-1200	 900	0.0	0.0
4
2 1 1 1 1 1 1
3 1 1 1 1 1 1
4 1 1 1 1 1 1
5 1 1 1 1 1 1
4
1 2 1	36.0	20.0	20.0	1000	492	492	200000	79300  0 7.85e-9
2 1 3	36.0	20.0	20.0	1000	492	492	200000	79300  0 7.85e-9
3 1 4	36.0	20.0	20.0	1000	492	492	200000	79300  0 7.85e-9
4 5 1	36.0	20.0	20.0	1000	492	492	200000	79300  0 7.85e-9
1
1
10.0
1.0
10.0
3
0 0 -9806.33
1
1 100 -200 -100 0 0 0
0
0
0
0
0
0 0 -9806.33
0
2
2 0 0.1 0
1 0 0 0.1
2
3 20 80 0.01 0.05
  0 0 0 0
  80 830 -0.05 0.07
4 0 0 0 0
  68 330 0.05 0.00
  80 830 -0.05 0.07
0
1
1 12e-6 10 10 20 10 10 -10
0
0 0 -9806.33
0
0
0
2
1 0 100 -900 600
2 0 -200 200 800
0
0
6     # dynamic modes
1     # subspace Jacobi
0     # consistent masses
1e-9  # tolerance
0.0   # shift
10.0  # exaggeration
1     # nodes with extra inertia
1  0.1  0 0 0
0     # elements with extra mass
6     # modes to animate
1 2 3 4 5 6
2     # pan rate
)";

// The natural frequencies exB.out prints (Hz, 6 decimals), consistent masses: Frame3DD's modal
// analysis of the structure prestressed by its last load case (docs/stability-and-modes.md).
constexpr std::array<double, 6> kExampleB2015Frequencies = {18.807942, 19.105451, 19.690439,
                                                            31.711570, 35.159165, 42.248953};

}  // namespace kinestat::io
