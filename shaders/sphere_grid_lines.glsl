// Selects the grid's ribbons in sphere_grid.frag (one program for the ribbons, one for the pole caps).
#define GRID_PART 0
