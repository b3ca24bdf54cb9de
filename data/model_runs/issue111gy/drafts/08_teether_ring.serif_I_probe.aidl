solid s {
    body = Rectangle(center=(0, 0), width=200, height=200)
    drawing d {
        c1 = Circle(center=(-50, 50), radius=28.75, construction=true)
        t1 = Text("ISLA", along=c1, size=6, font="sans:Bold", fill=true)
        c2 = Circle(center=(50, 50), radius=28.75, construction=true)
        t2 = Text("LISA", along=c2, size=6, font="sans:Bold", fill=true, flip=true)
        c3 = Circle(center=(-50, -50), radius=28.75, construction=true)
        t3 = Text("I I I", along=c3, size=6, font="sans:Bold", fill=true)
        t4 = Text("I", position=(50, -50), size=6, font="sans:Bold", fill=true)
    }
}
