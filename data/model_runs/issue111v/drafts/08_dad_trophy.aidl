# Gifts: a Father's Day trophy of 6 mm plywood, two parts glued. The plaque is 100 mm
# wide and 130 mm tall (tabs included), top corners rounded 8 mm, with a five-pointed
# star (outer radius 30, inner 13 mm, a tip up) centred 10 mm above its top edge.
# "BEST" and "DAD" engraved filled in sans Bold, 18 mm cap height, centred, baselines
# 80 mm and 50 mm above the plaque's bottom. Its bottom edge has two 20 mm tabs
# (tab_and_slot, glued: no screws) going into two mortises (0.1 mm clearance) in a
# base of 140 x 60 mm with 6 mm corner radius, centred on the base. "FATHER'S DAY 2026"
# engraved 5 mm high on the base, 20 mm in front of (below) its centre.
import "std/joints.aidl"
thickness 6 mm

param tab_w = 20 mm, min = 10 mm, max = 30 mm

assembly trophy {
    solid plaque {
        body = RoundedRectangle(center=(0, 59), width=100, height=130, corner_radii=[8, 8, 0, 0])
        star = Star(center=(0, 134), points=5, outer_radius=30, inner_radius=13)
        joint = tab_and_slot(part="tab", length=100 mm, thickness=6 mm, tabs=2, tab=tab_w,
                             screw=0, cx=0 mm, cy=0 mm)
        star.center.y == body.bb.top + 10 mm
        AlignCenterX(star, body)
        drawing words {
            best = Text("BEST", (0, 74), size=18, font="sans:Bold", fill=true)
            dad = Text("DAD", (0, 44), size=18, font="sans:Bold", fill=true)
        }
        words.best.position == (body.center.x, body.bb.bottom + 80 mm)
        words.dad.position == (body.center.x, body.bb.bottom + 50 mm)
    }

    solid base {
        foot = RoundedRectangle(center=(160, 0), width=140, height=60, corner_radius=6)
        mortise = tab_and_slot(part="slot", length=100 mm, thickness=6 mm, tabs=2, tab=tab_w,
                               screw=0, clearance=0.1 mm, cx=160 mm, cy=0 mm)
        drawing label { t = Text("FATHER'S DAY 2026", (160, -20), size=5, valign="middle") }
        label.t.position == (foot.center.x, foot.center.y - 20 mm)
    }
    RightOf(base, plaque, gap=10)

    assert plaque.body.width == 100 mm and plaque.body.height == 130 mm, "plaque 100 x 130"
    assert plaque.star.outer_radius == 30 mm and plaque.star.inner_radius == 13 mm, "star 30/13"
    assert base.foot.width == 140 mm and base.foot.height == 60 mm, "base 140 x 60"
    assert plaque.joint.tabs == 2 and base.mortise.tab == 20 mm, "two 20 mm tabs"
}
