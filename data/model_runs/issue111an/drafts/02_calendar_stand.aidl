# Request (office): a desk calendar stand for 100 x 70 mm month cards, 3 mm ply.
# Back panel 110 x 90 with a 6 mm ledge slot? no: two parts crossing by a halving:
# a back panel 110 wide x 90 tall with a 30 mm halving slot up from the middle of its
# bottom edge and "2027" engraved 10 mm tall 12 mm below its top; a foot 110 long x 40
# tall with a 20 mm halving slot down from the middle of its top edge (the depths add
# up to the foot's 40 - 10 = 30 + ... overlap: 50 mm), and a 100 mm x 3.5 mm card groove
# (a closed slot) in the back panel 15 mm above its bottom edge, where the cards stand.
import "std/joints.aidl"
thickness 3 mm

assembly calendar {
    solid back {
        body = Rectangle(center=(0, 45), width=110, height=90)
        # FIX after the first valid program: depths must add up to the foot height 40,
        # not 50 (the back stood 10 mm below the foot and rocked)
        h = cross_halving(depth=20 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                          cx=0 mm, cy=0 mm)
        hole groove {
            g = Rectangle(center=(-30, 15), width=40, height=3.5)
            g2 = Rectangle(center=(30, 15), width=40, height=3.5)
        }
        drawing year {
            t = Text("2027", position=(0, 68), size=10, font="sans:Bold", fill=true)
        }
        assert body.bb.top - year.t.position.y == 12 mm + 10 mm, "2027 top 12 below the top"
    }
    solid foot {
        body = Rectangle(center=(150, 20), width=110, height=40)
        h = cross_halving(depth=20 mm, thickness=3 mm, clearance=0.1 mm, cx=150 mm, cy=40 mm)
    }
    assert back.h.depth + foot.h.depth == 40 mm, "depths add up to the overlap"
}
