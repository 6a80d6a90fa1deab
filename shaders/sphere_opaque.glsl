// Selects the opaque cream ball in sphere.frag (one program per look); its grid and poles are drawn over it as lines
// by sphere_grid.frag.
#define SPHERE_LOOK 0
