# Request (pets): a raised double dog-bowl stand from 6 mm plywood, glued, four parts:
# - top 460 x 240 mm, corners R20, two 180 mm holes for the bowls (their rims rest on the
#   top), centres 220 mm apart, centred on the top; its surface 150 mm above the floor.
# - two legs 240 mm deep under the top, their middles 12 mm in from the top's ends, each
#   with two 30 mm tabs through the top (glued mortises); a paw print cut out of each leg
#   (a pad 36 x 28 mm and four toes 12 x 16 mm); a cross-halving slot from the floor up
#   60 mm in the leg's middle.
# - a stretcher 460 x 120 mm standing on the floor between the legs, cross-halved into them
#   (slots 60 mm down from its top edge under each leg), "BUDDY" cut through as bold sans
#   stencil letters 40 mm high in its middle.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
top_w = 460 mm
top_d = 240 mm
bowl_d = 180 mm
bowl_pitch = 220 mm
height = 150 mm
leg_in = 12 mm
leg_h = height - t + t          # to the shoulders under the top, plus tabs through it
str_h = 120 mm
leg_x = top_w / 2 - leg_in

def leg_panel() -> solid {
    body = Rectangle(center=(0, 0), width=top_d, height=leg_h)
    tabs = tab_and_slot(part="tab", length=top_d, thickness=t, tabs=2, tab=30 mm, screw=0,
                        cx=0 mm, cy=leg_h / 2)
    halving = cross_halving(depth=str_h / 2, thickness=t, rotation=180 deg, cx=0 mm, cy=-leg_h / 2)
    hole paw {
        pad = Ellipse(center=(0, 10), rx=18, ry=14)
        toe1 = Ellipse(center=(-24, 34), rx=6, ry=8, rotation=20 deg)
        toe2 = Ellipse(center=(-8, 44), rx=6, ry=8)
        toe3 = Ellipse(center=(8, 44), rx=6, ry=8)
        toe4 = Ellipse(center=(24, 34), rx=6, ry=8, rotation=-20 deg)
    }
}

assembly bowl_stand {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=top_w, height=top_d, corner_radius=20)
        hole bowls {
            left = Circle(center=(-bowl_pitch / 2, 0), diameter=bowl_d)
            right = Circle(center=(bowl_pitch / 2, 0), diameter=bowl_d)
        }
        left_mortise = tab_and_slot(part="slot", length=top_d, thickness=t, tabs=2, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=-leg_x, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=top_d, thickness=t, tabs=2, tab=30 mm,
                                     screw=0, rotation=90 deg, cx=leg_x, cy=0 mm)
    }

    leg_a = leg_panel()
    leg_b = leg_panel()

    solid stretcher {
        body = Rectangle(center=(0, 0), width=top_w, height=str_h)
        left_halving = cross_halving(depth=str_h / 2, thickness=t, cx=-leg_x, cy=str_h / 2)
        right_halving = cross_halving(depth=str_h / 2, thickness=t, cx=leg_x, cy=str_h / 2)
        hole name {
            word = Text("BUDDY", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                        stencil=true)
        }
    }

    Below(leg_a, top, gap=10)
    AlignLeft(leg_a, top)
    RightOf(leg_b, leg_a, gap=10)
    AlignTop(leg_b, leg_a)
    Below(stretcher, leg_a, gap=10)
    AlignLeft(stretcher, top)

    # the request's numbers
    assert top.body.width == 460 mm and top.body.height == 240 mm, "top 460 x 240"
    assert top.bowls.left.diameter == 180 mm, "bowl holes 180 mm"
    assert top.bowls.right.center.x - top.bowls.left.center.x == 220 mm, "bowls 220 mm apart"
    assert (top.bowls.right.center.x + top.bowls.left.center.x) / 2 == top.body.center.x, "bowls centred"
    assert leg_a.body.height - 6 mm + 6 mm == 150 mm, "surface 150 mm above the floor"
    assert top.body.bb.right - top.right_mortise.slot[0].center.x == 12 mm, "legs 12 mm in"
    assert stretcher.right_halving.cut.bb.height + leg_a.halving.cut.bb.height == 120 mm, "halvings meet"
    assert leg_a.halving.cut.bb.height == 60 mm, "leg slot 60 mm up"
    assert stretcher.right_halving.cut.center.x - stretcher.body.center.x == top.right_mortise.slot[0].center.x - top.body.center.x, "stretcher slots under the legs"
    assert stretcher.name.word.size == 40 mm, "BUDDY 40 mm"
}
