' EXPECT: 3: Type mismatch
PRINT USING "##.#"; 2.5
PRINT USING "##.#"; "two"
