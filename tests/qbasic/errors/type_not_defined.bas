' EXPECT: 2: Type not defined
DIM p AS Point3
