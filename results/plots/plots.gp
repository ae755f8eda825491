# written by tools/bench_report.c: error against cost per accuracy scene
set terminal pngcairo size 800,560 font 'sans,10'
set logscale xy
set grid
set key top right
set format y '10^{%L}'
set xlabel 'ms per 1/60 s of simulated time (log)'
set output 'projectile.png'
set title 'projectile: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'position error (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'projectile_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'projectile_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'projectile_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'projectile_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000224 4.79681e-06
0.000629 0.083334
e
set output 'constant_spin.png'
set title 'constant_spin: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'angle error (rad) (log; 0 drawn at 1e-12)' noenhanced
plot 'constant_spin_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'constant_spin_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'constant_spin_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'constant_spin_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000237 1.63913e-07
0.000619 4.45545e-06
e
set output 'pendulum_5.png'
set title 'pendulum_5: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'period error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'pendulum_5_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'pendulum_5_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'pendulum_5_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'pendulum_5_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000661 6.60302e-06
0.000775 0.000115291
e
set output 'pendulum_90.png'
set title 'pendulum_90: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'period error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'pendulum_90_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'pendulum_90_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'pendulum_90_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'pendulum_90_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000674 8.47884e-05
0.000798 0.071545
e
set output 'rolling_disc.png'
set title 'rolling_disc: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'distance error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'rolling_disc_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'rolling_disc_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'rolling_disc_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'rolling_disc_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.001527 0.00276654
0.001311 0.0097934
e
set output 'sliding_box.png'
set title 'sliding_box: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'distance error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'sliding_box_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'sliding_box_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'sliding_box_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'sliding_box_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.001579 0.00278314
0.001617 0.0114681
e
set output 'sticking_box.png'
set title 'sticking_box: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'creep (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'sticking_box_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'sticking_box_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'sticking_box_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'sticking_box_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.001164 1.42628e-05
0.001559 0.000991256
e
set output 'bounce_050.png'
set title 'bounce_050: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'apex error (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'bounce_050_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'bounce_050_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'bounce_050_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'bounce_050_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000291 0.00103378
0.000796 0.00848962
e
set output 'bounce_100.png'
set title 'bounce_100: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'apex error (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'bounce_100_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'bounce_100_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'bounce_100_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'bounce_100_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000278 0.00520158
0.000712 0.00904442
e
set output 'collision_1d.png'
set title 'collision_1d: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'velocity error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'collision_1d_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'collision_1d_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'collision_1d_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'collision_1d_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000387 9.48637e-09
0.000959 1.03818e-08
e
set output 'bullet_block.png'
set title 'bullet_block: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'block speed error (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'bullet_block_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'bullet_block_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'bullet_block_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'bullet_block_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.001532 7.24536e-09
0.001323 7.24536e-09
e
set output 'stack_15.png'
set title 'stack_15: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'top displacement (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'stack_15_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'stack_15_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'stack_15_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'stack_15_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.006583 0.00434017
0.01078 0.0418461
e
set output 'stack_30.png'
set title 'stack_30: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'top displacement (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'stack_30_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'stack_30_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'stack_30_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'stack_30_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.014002 0.0173569
0.021442 0.211076
e
set output 'pyramid_20.png'
set title 'pyramid_20: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'max drift (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'pyramid_20_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'pyramid_20_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'pyramid_20_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'pyramid_20_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.213332 0.00350874
0.339987 0.064699
e
set output 'pyramid_100.png'
set title 'pyramid_100: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'max drift (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'pyramid_100_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'pyramid_100_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'pyramid_100_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'pyramid_100_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
9.36409 0.0621934
12.839 4.91797
e
set output 'mass_ratio.png'
set title 'mass_ratio: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'sink (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'mass_ratio_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'mass_ratio_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'mass_ratio_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'mass_ratio_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.00593 0.00775814
0.006526 0.043375
e
set output 'chain_ball.png'
set title 'chain_ball: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'mean summed joint gap (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'chain_ball_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'chain_ball_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'chain_ball_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'chain_ball_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.033559 0.0156535
0.019336 1.68448
e
set output 'elastic_balls.png'
set title 'elastic_balls: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'energy drift (rel) (log; 0 drawn at 1e-12)' noenhanced
plot 'elastic_balls_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'elastic_balls_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'elastic_balls_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'elastic_balls_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.013984 0.000396722
0.015415 6.54378e-07
e
set output 'mass_spring.png'
set title 'mass_spring: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'position error (m) (log; 0 drawn at 1e-12)' noenhanced
plot 'mass_spring_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'mass_spring_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'mass_spring_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'mass_spring_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.000302 0.000114322
0.000595 0.00191957
e
set output 'far_pyramid.png'
set title 'far_pyramid: error against cost (filled: Pareto front, ringed: default)' noenhanced
set ylabel 'drift (ULP at 65 km) (log; 0 drawn at 1e-12)' noenhanced
plot 'far_pyramid_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \
     'far_pyramid_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' title 'tumble Pareto front', \
     'far_pyramid_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 sweep', \
     'far_pyramid_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' title 'Box2D Pareto front', \
     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 substeps / 8-3)'
0.045629 0.0418703
0.102213 0.95697
e
set output 'scaling.png'
set title 'pyramids of base 10 to 140: step time against body count'
set xlabel 'bodies (log)'
set ylabel 'ms per step (log)'
set format y '%g'
set key top left
plot 'scaling.dat' using 1:2 with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'tumble (4 substeps)', \
     'scaling.dat' using 1:3 with linespoints pt 5 lw 2 lc rgb '#d62728' title 'Box2D 2.4.1 (8/3)'
