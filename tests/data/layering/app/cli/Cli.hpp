// Fixture: a header the GUI fixture includes.
#pragma once
