# Request: "My daughter's St Patrick's Day leprechaun trap, in 3 mm birch ply: a closed
# finger-jointed box 160 x 120 x 100 mm outside. In its top a trapdoor 70 x 70 mm that
# gives way when the leprechaun steps on it: cut free on three sides, hinged on its left by
# a living-hinge band 14 mm wide. Behind the trapdoor a sign 80 x 36 mm (corners R4) with
# FREE GOLD fill-engraved (bold, 9 mm tall), on a post 16 mm wide standing 40 mm above the
# lid, glued by a 10 mm tenon into a mortise in the lid (0.1 mm clearance), the sign's
# middle 47 mm behind the lid's middle. A flat ladder 150 mm long and 40 mm wide with five
# rungs leans against the right side, its top on the box's top edge. On the front wall
# engrave a filled shamrock over LEPRECHAUN and TRAP. Kerf 0.15 mm."

import "std/joints.aidl"
import "std/plates.aidl"

units mm
t = 3 mm
thickness t
kerf 0.15 mm

box_h = 100 mm
flap = 70 mm
band = 14 mm
sign_back = 47 mm
ladder_len = 150 mm
lean = acos(box_h / ladder_len)      # from vertical: the top on the box's top edge

assembly trap {
    box = finger_box(length=160 mm, depth=120 mm, height=box_h, thickness=t)

    # the trapdoor: a 1 mm slit on three sides, a living hinge (0.5 mm slots) on the left,
    # written about the lid's middle (CutInto takes a hole, not a cut)
    hole trapdoor {
        path = Polyline([(-flap / 2 - band, flap / 2), (flap / 2, flap / 2), (flap / 2, -flap / 2),
                         (-flap / 2 - band, -flap / 2)], construction=true)
        u = Stroke(path, width=1 mm, cap="flat")
        hole hinge = living_hinge(width=band, height=flap, kerf_width=0.5 mm, overrun=0.5 mm,
                                  cx=-flap / 2 - band / 2, cy=0 mm)
    }
    Rigid(trapdoor)
    Coincident(trapdoor.path.points[1], box.lid.bb.center + (flap / 2, flap / 2))
    CutInto(trapdoor, box.lid)

    # the sign's mortise in the lid
    hole mortise {
        r = Rectangle(center=(0, 0), width=10 mm + 0.1 mm, height=t + 0.1 mm)
    }
    Coincident(mortise.r.center, box.lid.bb.center + (0, sign_back))
    CutInto(mortise, box.lid)

    solid sign {
        board = RoundedRectangle(center=(0, t + 40 mm + 18 mm), width=80, height=36, corner_radius=4)
        post = Rectangle(bottom_left=(-8, 0), width=16, height=t + 40 mm + 2 mm)
        tenon = tab_and_slot(part="tab", length=16 mm, thickness=t, tabs=1, tab=10 mm, screw=0,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing words {
            w = Text("FREE GOLD", position=(0, t + 40 mm + 18 mm), size=9, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    solid ladder {
        rail_l = Rectangle(bottom_left=(-20, 0), width=8, height=ladder_len)
        rail_r = Rectangle(bottom_left=(12, 0), width=8, height=ladder_len)
        for i in range(5) {
            rung = Rectangle(center=(0, 20 + i * 27.5), width=30, height=6)
        }
        AllowOverlap(rail_l, rail_r, rung)    # the spaces between the rungs are meant
    }

    drawing front_art {
        leaf_a = Circle(center=(0, 31), radius=6, fill=true)
        leaf_b = Circle(center=(-5.2, 22), radius=6, fill=true)
        leaf_c = Circle(center=(5.2, 22), radius=6, fill=true)
        stem = Stroke(Polyline([(0, 24), (2, 14), (5, 10)]), width=2)
        word1 = Text("LEPRECHAUN", position=(0, -2), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        word2 = Text("TRAP", position=(0, -26), size=18, font="sans:Bold", valign="middle",
                     fill=true)
    }
    CenterInside(front_art, box.front)
    CutInto(front_art, box.front)

    # on the sheet: sign and ladder beside the box's net
    RightOf(sign, box, gap=10 mm)
    AlignTop(sign, box)
    RightOf(ladder, box, gap=10 mm)
    Below(ladder, sign, gap=10 mm)

    # in 3D: the sign in its mortise, the ladder leaning on the right side
    Place(sign, position=(0, sign_back + t / 2, box_h - t), face="front")
    Place(ladder, position=(80 mm + ladder_len * sin(lean), 0, 0), face=(cos(lean), 0, sin(lean)),
          up=(-sin(lean), 0, cos(lean)))

    # the request's numbers
    assert box.front.bb.width == 160 mm and box.left.bb.height == 120 mm, "160 x 120"
    assert box.front.bb.height == 100 mm, "100 mm tall"
    assert trapdoor.path.points[1].x - trapdoor.path.points[0].x == flap + band, "flap and band along the top slit"
    assert trapdoor.path.points[1].y - trapdoor.path.points[2].y == 70 mm, "trapdoor 70 mm"
    assert trapdoor.hinge.width == 14 mm, "hinge band 14 mm"
    assert sign.board.bb.width == 80 mm and sign.board.bb.height == 36 mm, "sign 80 x 36"
    assert sign.board.bb.bottom - sign.tenon.gap[0].bb.top >= 40 mm - 0.01 mm, "post stands 40 mm above the lid"
    assert mortise.r.bb.width == 10.1 mm, "mortise 10 mm + 0.1"
    assert mortise.r.center.y - (trapdoor.path.points[1].y) >= 5 mm, "mortise clear of the trapdoor"
    assert sign.words.w.bb.width <= 80 mm - 2 * 4 mm, "FREE GOLD inside the sign"
    assert ladder.bb.height == 150 mm and ladder.bb.width == 40 mm and len(ladder.rung) == 5,
        "ladder 150 x 40, five rungs"
    assert front_art.word1.bb.width <= 160 mm - 2 * 12 mm, "LEPRECHAUN inside the front"
}
