// Selects the chart's pole caps in sphere_grid.frag (one program for the ribbons, one for the pole caps).
#define GRID_PART 1
