// Fixture: a header the geometry fixture includes.
#pragma once
