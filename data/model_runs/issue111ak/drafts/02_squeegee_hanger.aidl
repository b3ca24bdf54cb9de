# Bathroom: a squeegee hanger that hooks over the top of an 8 mm glass shower screen,
# cut from 6 mm acrylic, three parts glued together:
# - two hook side profiles (side view): a 6 mm front leg 36 mm long outside the glass,
#   a 9 mm gap for the 8 mm glass, a 6 mm back leg 98 mm long on the shower side, and at
#   the back leg's foot a bracket 45 mm deep (out from the back leg) and 24 mm tall with
#   two mortises for the shelf; outer corners rounded R3;
# - a shelf 100 mm between the side profiles and 45 mm deep, with two 12 mm tabs at each
#   end through the profiles' mortises, and a U slot 22 mm wide and 30 mm deep from its
#   front edge that the squeegee's handle drops into; the slot's mouth corners R3.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm          # acrylic
glass_gap = 9 mm  # 8 mm glass + 1 mm play
front_leg = 36 mm
back_leg = 98 mm
bracket_depth = 45 mm
bracket_h = 24 mm
shelf_span = 100 mm   # between the side profiles
shelf_depth = 45 mm
u_w = 22 mm
u_d = 30 mm

def hook_side() -> solid {
    # x = 0 is the outside face of the glass, y = 0 its top edge
    bridge = Rectangle(corner=(-t, 0), opposite=(glass_gap + t, t))
    front = Rectangle(corner=(-t, t - front_leg), opposite=(0, t))
    back = Rectangle(corner=(glass_gap, t - back_leg), opposite=(glass_gap + t, t))
    bracket = Rectangle(corner=(glass_gap, t - back_leg),
                        opposite=(glass_gap + t + bracket_depth, t - back_leg + bracket_h))
    # the shelf's mid-plane runs along the bracket's middle
    mortise = tab_and_slot(part="slot", length=shelf_depth, thickness=t, tabs=2, tab=12 mm,
                           screw=0, cx=glass_gap + t + shelf_depth / 2,
                           cy=t - back_leg + bracket_h / 2)
    Fillet([bridge.top_left, bridge.top_right, front.bottom_left, front.bottom_right,
            bracket.top_right, bracket.bottom_right, bracket.bottom_left], 3)
}

solid shelf_plate() {
    body = Rectangle(center=(0, 0), width=shelf_span + 2 * t, height=shelf_depth)
    left_tabs = tab_and_slot(part="tab", length=shelf_depth, thickness=t, tabs=2, tab=12 mm,
                             screw=0, rotation=90 deg, cx=-(shelf_span / 2 + t), cy=0)
    right_tabs = tab_and_slot(part="tab", length=shelf_depth, thickness=t, tabs=2, tab=12 mm,
                              screw=0, rotation=-90 deg, cx=shelf_span / 2 + t, cy=0)
    # the front edge is the top one (y = +depth/2)
    hole handle_slot {
        u = Rectangle(corner=(-u_w / 2, shelf_depth / 2 - u_d + u_w / 2),
                      opposite=(u_w / 2, shelf_depth / 2))
        end = Circle(center=(0, shelf_depth / 2 - u_d + u_w / 2), diameter=u_w)
        # FIX after the first valid program: an `over = Rectangle(..., overrun=true)` 1 mm past
        # the front edge drew W0502 ("cuts nothing: it lies outside solid"); the U opens
        # cleanly without it, so it is gone.
    }
    Fillet([body.top, handle_slot.u], 3)
}

assembly squeegee_hanger {
    left = hook_side()
    right = hook_side()
    shelf = shelf_plate()
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(shelf, left, gap=10)
    AlignLeft(shelf, left)

    assert left.back.bb.left - left.front.bb.right == 9 mm, "9 mm glass gap"
    assert left.front.bb.height == 36 mm, "front leg 36 mm"
    assert left.back.bb.height == 98 mm, "back leg 98 mm"
    assert left.bracket.bb.right - left.back.bb.right == 45 mm, "bracket 45 mm deep"
    assert left.bracket.bb.height == 24 mm, "bracket 24 mm tall"
    assert shelf.body.bb.width - 2 * 6 mm == 100 mm, "100 mm between the sides"
    assert shelf.body.bb.height == 45 mm, "shelf 45 mm deep"
    assert shelf.handle_slot.u.bb.width == 22 mm, "U slot 22 mm wide"
    assert shelf.body.bb.top - shelf.handle_slot.end.bb.bottom == 30 mm, "U slot 30 mm deep"
    assert shelf.left_tabs.tabs == 2 and shelf.left_tabs.tab == 12 mm, "two 12 mm tabs"
}
