# A laser-cut box 100 x 60 x 40 mm (outer) from 3 mm plywood with finger
# joints: the six flat panels laid out side by side for cutting.

param L = 100 mm   # length (x)
param W = 60 mm    # width (y)
param H = 40 mm    # height (z)
param t = 3 mm     # material thickness

# finger counts per edge (odd, so both ends of an edge match)
nL = 9
nW = 5
nH = 3

# A panel w x h with finger notches of depth t cut along its edges.
# x_phase / y_phase: which segments (0 = even, 1 = odd) are cut out on the
# horizontal (top/bottom) and vertical (left/right) edges.
def panel(w, h, nx, ny, x_phase, y_phase) -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    hole notches {
        for i in range(nx) {
            if i % 2 == x_phase {
                nt = Rectangle(center=(-w / 2 + (i + 0.5) * w / nx, h / 2 - t / 2), width=w / nx, height=t)
                nb = Rectangle(center=(-w / 2 + (i + 0.5) * w / nx, -h / 2 + t / 2), width=w / nx, height=t)
            }
        }
        for j in range(ny) {
            if j % 2 == y_phase {
                nl = Rectangle(center=(-w / 2 + t / 2, -h / 2 + (j + 0.5) * h / ny), width=t, height=h / ny)
                nr = Rectangle(center=(w / 2 - t / 2, -h / 2 + (j + 0.5) * h / ny), width=t, height=h / ny)
            }
        }
    }
    Rigid(self)
}

assembly box {
    # bottom and lid: fingers at the even segments (odd ones cut away)
    bottom = panel(w=L, h=W, nx=nL, ny=nW, x_phase=1, y_phase=1)
    lid = panel(w=L, h=W, nx=nL, ny=nW, x_phase=1, y_phase=1)
    # front and back: even segments cut on the top/bottom edges, odd on the sides
    front = panel(w=L, h=H, nx=nL, ny=nH, x_phase=0, y_phase=1)
    back = panel(w=L, h=H, nx=nL, ny=nH, x_phase=0, y_phase=1)
    # ends: even segments cut everywhere (they take the front's side fingers)
    left_end = panel(w=W, h=H, nx=nW, ny=nH, x_phase=0, y_phase=0)
    right_end = panel(w=W, h=H, nx=nW, ny=nH, x_phase=0, y_phase=0)

    # lay them out flat with 5 mm between parts
    RightOf(lid, bottom, gap=5)
    Below(front, bottom, gap=5)
    Below(back, lid, gap=5)
    Below(left_end, front, gap=5)
    Below(right_end, back, gap=5)
    AlignLeft(front, bottom)
    AlignLeft(back, lid)
    AlignLeft(left_end, front)
    AlignLeft(right_end, back)
    AlignTop(lid, bottom)
    Fixed(bottom)
}
