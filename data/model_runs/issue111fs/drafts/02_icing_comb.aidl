# Request (kitchen): "A cake icing comb for the sides of layer cakes, from 3 mm food-safe clear
# acrylic: one plate 240 x 100 mm, each edge a different finish. Top long edge: a zig-zag of
# 12 teeth, 20 mm pitch, 8 mm deep (tips on the edge line). Bottom long edge: 8 half-round
# scallops R8 at 30 mm pitch, centred along the edge. Left short edge: square ribs, 5 mm notches
# 5 mm deep at 10 mm pitch, 8 of them centred on the edge. Right short edge left straight and sharp
# for smoothing. A 50 x 20 mm finger slot in the middle to hold it, and each edge's name engraved
# beside it (ZIG-ZAG, SCALLOP, RIB, SMOOTH), at least 4 mm from any cut."

W = 240 mm
H = 100 mm
pitch_z = 20 mm
depth_z = 8 mm
teeth = 12
scallops = 8
pitch_s = 30 mm
r_s = 8 mm
ribs = 8
pitch_r = 10 mm
rib = 5 mm

solid comb {
    # the outline: bottom edge, straight right edge, then the zig-zag from right to left
    zig = [(W / 2 - (k + 1) * pitch_z / 2, H / 2 - depth_z * ((k + 1) % 2)) for k in range(2 * teeth)]
    outline = Polygon([(-W / 2, -H / 2), (W / 2, -H / 2), (W / 2, H / 2)] + zig)

    hole scallop {
        for i in range(scallops) {
            c = Circle(center=(-(scallops - 1) * pitch_s / 2 + i * pitch_s, -H / 2), radius=r_s)
        }
    }
    hole ribs_cut {
        for i in range(ribs) {
            # 1 mm past the edge so the notch opens cleanly
            n = Rectangle(center=(-W / 2 + rib / 2 - 0.5 mm, -(ribs - 1) * pitch_r / 2 + i * pitch_r),
                          width=rib + 1 mm, height=rib)
        }
    }
    hole grip {
        s = Slot(center=(0, 0), length=50, width=20)
    }

    drawing names {
        top = Text("ZIG-ZAG", position=(0, H / 2 - depth_z - 10), size=6, valign="middle")
        bottom = Text("SCALLOP", position=(0, -H / 2 + r_s + 10), size=6, valign="middle")
        left = Text("RIB", position=(-W / 2 + rib + 10, 0), size=6, valign="middle", rotation=90 deg)
        right = Text("SMOOTH", position=(W / 2 - 10, 0), size=6, valign="middle", rotation=-90 deg)
    }

    # the request's numbers
    assert outline.bb.width == 240 mm and outline.bb.height == 100 mm, "plate 240 x 100"
    assert len(zig) == 2 * 12, "12 zig-zag teeth"
    assert outline.bb.top - zig[0][1] == 8 mm, "teeth 8 mm deep"
    assert zig[0][0] - zig[2][0] == 20 mm, "20 mm pitch"
    assert len(scallop.c) == 8, "8 scallops"
    assert scallop.c[1].center.x - scallop.c[0].center.x == 30 mm, "scallops at 30 mm pitch"
    assert scallop.c[0].radius == 8 mm, "R8 scallops"
    assert scallop.c[0].center.y == outline.bb.bottom, "scallops centred on the bottom edge"
    assert abs(scallop.c[0].center.x + scallop.c[7].center.x) < 0.001 mm, "scallops centred along the edge"
    assert len(ribs_cut.n) == 8, "8 rib notches"
    assert ribs_cut.n[0].bb.right - outline.bb.left == 5 mm, "rib notches 5 mm deep"
    assert ribs_cut.n[0].height == 5 mm, "rib notches 5 mm wide"
    assert ribs_cut.n[1].center.y - ribs_cut.n[0].center.y == 10 mm, "ribs at 10 mm pitch"
    assert grip.s.length == 50 mm and grip.s.width == 20 mm, "finger slot 50 x 20"
    # labels clear of every cut
    assert distance(names.top, grip) >= 4 mm and names.top.bb.top <= outline.bb.top - 8 mm - 4 mm, "ZIG-ZAG clear"
    assert distance(names.bottom, scallop) >= 4 mm and distance(names.bottom, grip) >= 4 mm, "SCALLOP clear"
    assert distance(names.left, ribs_cut) >= 4 mm, "RIB clear"
    assert outline.bb.right - names.right.bb.right >= 4 mm, "SMOOTH clear of the edge"
}
