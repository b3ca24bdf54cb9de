# Home: TV-remote caddy, 3 mm plywood. An open-top finger-jointed box 180 long x 90 deep x 80
# tall outside, 10 mm fingers. A finger scoop in the front: a half circle R25 cut down from the
# middle of the front's top edge. "REMOTES" engraved 10 mm tall on the front, centred across,
# its middle 10 mm below the front's centre.
import "std/joints.aidl"

thickness 3 mm

assembly caddy {
    box = finger_box(length=180 mm, depth=90 mm, height=80 mm, thickness=3 mm, finger=10 mm, closed=false)

    hole scoop {
        c = Circle(center=(0, 0), radius=25)
    }
    AlignCenterX(scoop, box.front)
    scoop.c.center.y == box.front.bb.top
    CutInto(scoop, box.front)

    drawing label {
        t = Text("REMOTES", (0, 0), size=10, valign="middle")
    }
    AlignCenterX(label, box.front)
    label.bb.center_y == box.front.bb.center_y - 10 mm
    CutInto(label, box.front)

    assert box.front.bb.width == 180 mm, "180 long"
    assert box.front.bb.height == 80 mm, "80 tall"
    assert box.left.bb.height == 90 mm, "90 deep"
    assert scoop.c.radius == 25 mm, "scoop R25"
    assert label.t.size == 10 mm, "10 mm letters"
}
