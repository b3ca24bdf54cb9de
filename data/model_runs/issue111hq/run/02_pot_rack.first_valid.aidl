# Request (kitchen): a wall pot rack in 6 mm birch ply. A shelf board 600 x 200 mm for lids
# and a colander on top, held by two brackets 200 mm tall into a 600 x 200 back plate
# screwed to the wall with M5 screws. Under the shelf the pans hang on S-hooks (6 mm wire)
# from a row of 8 round holes, 12 mm across, 60 mm apart centre to centre, the row centred
# along the shelf and 15 mm in from its front edge (the edge away from the wall).

import "std/stands.aidl"

thickness 6 mm

hook_count = 8
hook_pitch = 60 mm
hook_d = 12 mm

assembly pot_rack {
    rack = wall_shelf(length=600 mm, depth=200 mm, height=200 mm, thickness=6 mm, screw=5)

    hole hook {
        c = Circle(center=(0, 0), diameter=hook_d)
    }
    hooks = LinearPattern(hook, hook_count, (hook_pitch, 0))
    CutInto(hook, rack.shelf)

    # the row is centred along the shelf, 15 mm in from its front (bottom, laid flat) edge
    hooks[0].c.center.x + hooks[hook_count - 1].c.center.x == 2 * rack.shelf.bb.center_x
    hooks[0].c.bottom.y == rack.shelf.bb.bottom + 15 mm - hook_d / 2

    assert len(hooks) == 8, "8 hook holes"
    assert hooks[1].c.center.x - hooks[0].c.center.x == 60 mm, "60 mm apart"
    assert hooks[0].c.diameter == 12 mm, "12 mm holes for 6 mm wire hooks"
    assert hooks[0].c.center.y - rack.shelf.bb.bottom == 15 mm, "15 mm in from the front edge"
    assert rack.shelf.bb.width == 600 mm, "shelf 600 long"
    assert abs((hooks[0].c.center.x + hooks[7].c.center.x) / 2 - rack.shelf.bb.center_x) < 0.01 mm,
        "the row is centred"
}
